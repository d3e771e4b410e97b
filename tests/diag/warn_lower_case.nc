o1003 (edited on a pc)
g90 g54 g00 x10. y20.
#1 = #1 + 1.
m30

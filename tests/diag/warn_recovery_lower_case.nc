%
o1058 (lower case from a cam post)
g90 g54 g00 x0. y0.
#1 = 0
while [#1 lt 3] do1
g01 x[#1 * 10.] f200.
#1 = #1 + 1
end1
m30
%

%
O1000 (An alarm in the middle of a run of constant blocks names its block)
G90 G00 X0 Y0
G01 X10. F100
X20.
G02 X30. Y0 I1.
X40.
M30
%

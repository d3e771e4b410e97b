; G28 in polar coordinate mode with a plane axis word: the intermediate
; point's polar reading is not modelled, so the run stops at the block
; with MBC0001 instead of moving somewhere the control might not. A Z-only
; G28 in G16 runs.
G17G90G16
G0X30.Y45.Z10.
G91G28Z0
G28X0Y0
M30

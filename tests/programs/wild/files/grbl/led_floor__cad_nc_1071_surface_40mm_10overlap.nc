(1071_surface_40mm_10overlap)
(T1  D=40 CR=0 - ZMIN=0 - face mill)
G90 G94
G17
G21
(When using Fusion 360 for Personal Use, the feedrate of)
(rapid moves is reduced to match the feedrate of cutting)
(moves, which can increase machining time. Unrestricted rapid)
(moves are available with a Fusion 360 Subscription.)

(Face2)
T1
S5000 M3
G54
G0 X300.207 Y178.484
Z10
G1 Z5 F1000
Z0 F333.3
Y159 F1000
Y0
X290.513
Y159
X280.82
Y0
X271.127
Y159
X261.433
Y0
X251.74
Y159
X242.047
Y0
X232.353
Y159
X222.66
Y0
X212.967
Y159
X203.273
Y0
X193.58
Y159
X183.887
Y0
X174.193
Y159
X164.5
Y0
X154.807
Y159
X145.113
Y0
X135.42
Y159
X125.727
Y0
X116.033
Y159
X106.34
Y0
X96.647
Y159
X86.953
Y0
X77.26
Y159
X67.567
Y0
X57.873
Y159
X48.18
Y0
X38.487
Y159
X28.793
Y0
X19.1
Y159
Z10
M5
M30

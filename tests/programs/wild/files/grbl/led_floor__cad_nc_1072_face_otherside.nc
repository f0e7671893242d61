(1072_face_otherside)
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
G0 X-0.427 Y-21.991
Z10
G1 Z5 F1000
Z0 F333.3
Y0 F1000
Y159
X18.947
Y0
X38.32
Y159
X57.693
Y0
X77.067
Y159
X96.44
Y0
X115.813
Y159
X135.187
Y0
X154.56
Y159
X173.933
Y0
X193.307
Y159
X212.68
Y0
X232.053
Y159
X251.427
Y0
X270.8
Y159
Z10
M5
M30

(Written for usina: the $ lines a Grbl setup file or a sender macro holds)
(Expected: reports do nothing, settings are recorded, $H homes once $22=1)
$$
$#
$G
$I
$N
$100=250.000 (x steps/mm)
$101=250.000
$102=250.000
$110=1000.000
$111=1000.000
$112=500.000
$12=0.002 (arc tolerance, mm)
$13=0
$22=1 (homing on; with $22=0, $H is error:5)
$27=1.000 (homing pull-off, mm)
$X
$H
G21 G90 G54
G0 X10 Y10
$J=G91 X5 F500 (jog: a feed move that changes no modal state)
$J=G53 Z-2 F300
G0 X0 Y0 (G0 and G90 are still active after the jogs)
M2

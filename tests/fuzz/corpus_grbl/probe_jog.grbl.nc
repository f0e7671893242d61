%
; Twin of probe_jog.ngc. Written for usina: what a sender macro streams to
; Grbl 1.1 - reports, a setting, a probe, jogs and a block-delete line.
$G
$#
$12=0.002
G21 G90 G94
G0 X20 Y20 Z10
G38.2 Z-5 F100            ; usina: contact at the target
G0 Z10
$J=G91 X5 F600            ; jog: a feed move, the modes stay G0 G90
$J=X30 Y25 F600
X40 Y20                   ; still G0 and G90 after the jogs
/G0 Z15                   ; Grbl has no block delete: this line runs
G1 Z0 F200
G2 X50 Y30 I10 J0
G0 Z10
M5
%

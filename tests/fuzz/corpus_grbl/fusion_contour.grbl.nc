%
(Twin of fusion_contour.ngc. Written for usina in the layout of Fusion 360 grbl output:)
(a 30 x 20 mm rectangle with 4 mm corner radii, two 1.5 mm passes)
(T1  D=3.175 CR=0. - ZMIN=-3. - flat end mill)
G90 G94
G17
G21

(2D Contour1)
T1
S12000 M3
G54
G0 X-1.5875 Y4.
Z15.
Z5.
G1 Z1. F300.
Z-1.5
G1 Y16. F800.
G2 X4. Y21.5875 I5.5875 J0.
G1 X26.
G2 X31.5875 Y16. I0. J-5.5875
G1 Y4.
G2 X26. Y-1.5875 I-5.5875 J0.
G1 X4.
G2 X-1.5875 Y4. I0. J5.5875
G1 Z-3. F300.
G1 Y16. F800.
G2 X4. Y21.5875 R5.5875
G1 X26.
G2 X31.5875 Y16. R5.5875
G1 Y4.
G2 X26. Y-1.5875 R5.5875
G1 X4.
G2 X-1.5875 Y4. R5.5875
G0 Z15.

M5
G28 G91 Z0.
G90
M30
%

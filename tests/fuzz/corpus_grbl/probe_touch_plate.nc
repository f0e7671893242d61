; Written for usina in the style of sender probe macros (bCNC, CNCjs):
; G38.2 toward a 19 mm touch plate, G92 sets Z, G38.3/G38.4/G38.5 variants.
; usina assumes contact at the target (no probe in a trace).
G21 G90 G94
G0 X20 Y20 Z10
G38.2 Z-20 F100      ; fast probe
G91 G0 Z2            ; back off 2 mm
G38.2 Z-5 F25        ; slow probe
G90
G92 Z19.0            ; the plate is 19 mm thick
G0 Z25
G38.3 X40 F200       ; probe without error when nothing is touched
G38.4 X30 F50        ; probe away, error if contact is not lost
G38.5 X20 F50        ; probe away without error
G0 Z30
M5
M30

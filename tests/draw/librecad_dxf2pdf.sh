#!/usr/bin/env bash
# Opens a DXF of usina draw in LibreCAD: `librecad dxf2pdf` must render the
# bracket's drawing (a PDF with more in it than LibreCAD's page of an empty
# drawing). Exits 77 (ctest: skipped) when LibreCAD is not installed
# (apt-get install librecad).
#   librecad_dxf2pdf.sh USINA EXAMPLES_DIR
set -euo pipefail
usina=$1
examples=$2
if ! command -v librecad > /dev/null; then
  echo "librecad is not installed: skipped"
  exit 77
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$usina" draw "$examples/bracket.ngc" --tool-table "$examples/tools.tbl" -o "$tmp/bracket.dxf"
printf 'M2\n' > "$tmp/empty.ngc"
"$usina" draw "$tmp/empty.ngc" -o "$tmp/empty.dxf"
# Qt needs no display with the offscreen platform.
QT_QPA_PLATFORM=offscreen XDG_RUNTIME_DIR="$tmp" timeout 300 \
  librecad dxf2pdf -a -t "$tmp/out" "$tmp/bracket.dxf" "$tmp/empty.dxf"
for f in bracket empty; do
  if [[ "$(head -c 4 "$tmp/out/$f.pdf")" != "%PDF" ]]; then
    echo "FAIL: LibreCAD wrote no PDF of $f.dxf"
    exit 1
  fi
done
drawn=$(stat -c %s "$tmp/out/bracket.pdf")
empty=$(stat -c %s "$tmp/out/empty.pdf")
if (( drawn < 2 * empty )); then
  echo "FAIL: LibreCAD's PDF of the bracket ($drawn bytes) is no bigger than of an empty drawing ($empty bytes)"
  exit 1
fi
echo "ok: LibreCAD rendered bracket.dxf ($drawn bytes of PDF, empty drawing $empty)"

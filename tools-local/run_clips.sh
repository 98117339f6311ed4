#!/bin/sh
# Runs the harness on every clip of bench/real/clip_set.py into $OUT/<clip>/ (results.csv, PNGs).
set -e
H=$(dirname "$0")/moving_object_harness
OUT=${OUT:-/tmp/mo/cpp}
R=/work/main/build/real-clips/root/usr/share
O=/usr/share/doc/opencv-doc
C=${CLIPDIR:-/tmp/mo/clips}   # cup.mp4, box.mp4: the .gz unpacked here once
mkdir -p "$C"
for c in cup box; do
  [ -s "$C/$c.mp4" ] || zcat "$O/opencv4/html/$c.mp4.gz" > "$C/$c.mp4"
done
for spec in "cup|$C/cup.mp4" "box|$C/box.mp4" "vtest|$O/examples/data/vtest.avi" \
  "megamind|$O/examples/data/Megamind.avi" "balle1|$R/pymecavideo/data/video/balle1-vp9.avi" \
  "inertie|$R/pymecavideo/data/video/Principe_inertie.avi" "force|$R/pymecavideo/data/video/Force_constante.avi" \
  "magnet|$R/pymecavideo/data/video/Effet_force_magnetique.ogv" \
  "cube|$R/visp-images-data/ViSP-images/mbt/cube/image*.pgm" \
  "ellipse|$R/visp-images-data/ViSP-images/ellipse-1/image.*.pgm"; do
  name=${spec%%|*}; src=${spec#*|}
  case " ${CLIPS:-$name} " in *" $name "*) ;; *) continue;; esac
  rm -rf "$OUT/$name"; mkdir -p "$OUT/$name"
  "$H" "$src" "$OUT/$name" > "$OUT/$name/results.csv" 2>/dev/null
done

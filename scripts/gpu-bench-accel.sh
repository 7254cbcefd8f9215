#!/bin/bash
# The walks of issue 41 on a GPU host: `penumbra bench --json` of each scene under --accel bvh,
# stackless and objects, alternated ROUNDS times so drifting clocks hit all alike
# (docs/PERFORMANCE.md, "Stackless walk and per-object boxes"). Pack first, here, after a Release
# build:
#   scripts/gpu-pack.sh build/penumbra /usr/share/games/doom/freedoom1.wad \
#       /usr/share/glmark2/models/bunny.obj /usr/share/assimp/models/BLEND/Suzanne_248.blend
# then on the GPU host (device tool `run`, carry [".gpu"]), from the checkout root:
#   OUT=$OUT scripts/gpu-bench-accel.sh
# Settings: ROUNDS (default 3), REPEATS (bench's timed runs, default 20), ACCELS (default
# "bvh stackless objects"), SCENES (default: cornell, suzanne, bunny-room, Freedoom E1M1).
# Results: $OUT/accel.jsonl, one bench object per line after a "# scene accel round" line.
set -euo pipefail
source .gpu/env.sh
B=.gpu/bin
OUT=${OUT:-./bench-accel-out}
ROUNDS=${ROUNDS:-3}
REPEATS=${REPEATS:-20}
ACCELS=${ACCELS:-"bvh stackless objects"}
mkdir -p "$OUT" /usr/share/games/doom /usr/share/glmark2/models /usr/share/assimp/models/BLEND
cp $B/freedoom1.wad /usr/share/games/doom/
cp $B/bunny.obj /usr/share/glmark2/models/
cp $B/Suzanne_248.blend /usr/share/assimp/models/BLEND/
SCENES=${SCENES:-"cornell|suzanne|bunny-room|/usr/share/games/doom/freedoom1.wad --map E1M1"}
IFS='|' read -r -a scenes <<< "$SCENES"
for round in $(seq 1 "$ROUNDS"); do
  for s in "${scenes[@]}"; do
    for accel in $ACCELS; do
      echo "# $s $accel $round" >> "$OUT/accel.jsonl"
      # shellcheck disable=SC2086
      $B/penumbra bench $s --repeats "$REPEATS" --json --accel "$accel" | tr -d '\n' >> "$OUT/accel.jsonl"
      echo >> "$OUT/accel.jsonl"
    done
  done
done

#!/bin/bash
# --cull-backfaces on a GPU host: `penumbra bench --json` of each scene with and without culling,
# alternated ROUNDS times so drifting clocks hit both alike (docs/PERFORMANCE.md, "Back-face
# culling"). Pack first, here, after a Release build:
#   scripts/gpu-pack.sh build/penumbra /usr/share/games/doom/freedoom1.wad \
#       /usr/share/glmark2/models/bunny.obj /usr/share/assimp/models/BLEND/Suzanne_248.blend
# then on the GPU host (device tool `run`, carry [".gpu"]), from the checkout root:
#   OUT=$OUT scripts/gpu-bench-cull.sh
# Settings: ROUNDS (default 3), REPEATS (bench's timed runs, default 20), SCENES (default: suzanne,
# bunny-room, Freedoom E1M1). Results: $OUT/cull.jsonl, one bench object per line after a
# "# scene flags round" line.
set -euo pipefail
source .gpu/env.sh
B=.gpu/bin
OUT=${OUT:-./bench-cull-out}
ROUNDS=${ROUNDS:-3}
REPEATS=${REPEATS:-20}
mkdir -p "$OUT" /usr/share/games/doom /usr/share/glmark2/models /usr/share/assimp/models/BLEND
cp $B/freedoom1.wad /usr/share/games/doom/
cp $B/bunny.obj /usr/share/glmark2/models/
cp $B/Suzanne_248.blend /usr/share/assimp/models/BLEND/
SCENES=${SCENES:-"suzanne|bunny-room|/usr/share/games/doom/freedoom1.wad --map E1M1"}
IFS='|' read -r -a scenes <<< "$SCENES"
for round in $(seq 1 "$ROUNDS"); do
  for s in "${scenes[@]}"; do
    for flags in "" "--cull-backfaces"; do
      echo "# $s ${flags:-none} $round" >> "$OUT/cull.jsonl"
      # shellcheck disable=SC2086
      $B/penumbra bench $s --repeats "$REPEATS" --json $flags | tr -d '\n' >> "$OUT/cull.jsonl"
      echo >> "$OUT/cull.jsonl"
    done
  done
done

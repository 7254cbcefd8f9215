#!/bin/bash
# Benchmarks and gallery renders of the presets on a GPU host (see docs/PERFORMANCE.md).
# Run from a checkout holding .gpu/ packed with the binary, freedoom1.wad and bunny.obj.
set -x
source .gpu/env.sh
B=.gpu/bin
mkdir -p /usr/share/games/doom /usr/share/glmark2/models
cp $B/freedoom1.wad /usr/share/games/doom/; cp $B/bunny.obj /usr/share/glmark2/models/
for s in cornell "/usr/share/games/doom/freedoom1.wad --map E1M1" bunny-room materials caffeine; do
  echo "== $s" >> $OUT/bench.txt
  penumbra bench $s --json >> $OUT/bench.txt 2>&1
done
penumbra render caffeine --width 1920 --height 1080 --spp 2048 -o $OUT/caffeine.png 2>&1 | tail -1 >> $OUT/render.txt
penumbra render bunny-room --width 1920 --height 1080 --spp 4096 -o $OUT/bunny-room.png 2>&1 | tail -1 >> $OUT/render.txt
penumbra render materials --width 1920 --height 1080 --spp 2048 -o $OUT/materials.png 2>&1 | tail -1 >> $OUT/render.txt
penumbra render /usr/share/games/doom/freedoom1.wad --map E1M1 --width 1920 --height 1080 --spp 1024 -o $OUT/e1m1.png 2>&1 | tail -1 >> $OUT/render.txt
penumbra render cornell --width 1024 --height 1024 --spp 4096 -o $OUT/cornell.png 2>&1 | tail -1 >> $OUT/render.txt

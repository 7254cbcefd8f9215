#!/bin/bash
# Benchmarks and gallery renders of imported scenes on a GPU host (see docs/PERFORMANCE.md).
# Run from a checkout holding .gpu/ packed with the binary, freedoom1.wad, bunny.obj,
# 2CylinderEngine.glb and scenes/*.json in .gpu/scenes; OUT names the output folder.
set -x
source .gpu/env.sh
B=.gpu/bin
mkdir -p /usr/share/games/doom /usr/share/glmark2/models /usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary
cp $B/freedoom1.wad /usr/share/games/doom/; cp $B/bunny.obj /usr/share/glmark2/models/; cp $B/2CylinderEngine.glb /usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/
penumbra info 2>&1 | head -3 > $OUT/info.txt
git rev-parse HEAD > $OUT/commit.txt 2>/dev/null
for s in "cornell" "/usr/share/games/doom/freedoom1.wad --map E1M1" "/usr/share/glmark2/models/bunny.obj" "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb" ".gpu/scenes/bunny-cornell.json"; do
  echo "== $s" >> $OUT/bench.txt
  penumbra bench $s --json >> $OUT/bench.txt 2>&1
  penumbra info $s 2>&1 | grep -A4 "^scene" >> $OUT/bench.txt
done
penumbra render /usr/share/games/doom/freedoom1.wad --map E1M1 --width 1920 --height 1080 --spp 1024 -o $OUT/e1m1.png 2>&1 | tail -1 >> $OUT/render.txt
penumbra render /usr/share/games/doom/freedoom1.wad --map E1M1 --width 1920 --height 1080 --spp 1024 -o $OUT/e1m1.exr 2>&1 | tail -1 >> $OUT/render.txt
penumbra render .gpu/scenes/engine.json --width 1920 --height 1080 --spp 1024 -o $OUT/engine.png 2>&1 | tail -1 >> $OUT/render.txt
penumbra render .gpu/scenes/bunny-cornell.json --width 1024 --height 1024 --spp 4096 -o $OUT/bunny-cornell.png 2>&1 | tail -1 >> $OUT/render.txt
penumbra render /usr/share/games/doom/freedoom1.wad --map E1M1 --width 1920 --height 1080 --spp 1 --bounces 4 2>&1 | tail -1 >> $OUT/render.txt

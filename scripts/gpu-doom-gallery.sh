#!/usr/bin/env bash
# The gallery pair of issue 9: id's DOOM1.WAD E1M1 from the player start with the torch off, by
# Penumbra (lit by its glowing textures, sector light levels, sky and lamps) and by the WebGPU
# renderer (../shared/peers/seed-webgpu, its --screenshot), from the same view: the peer's camera
# (eye 56 units above the floor, 90-degree vertical field of view, looking along the start's
# angle) at the peer's size.
#
#   scripts/gpu-doom-gallery.sh pack     here: packs build/penumbra (.gpu/) and the peer (.peer/)
#   scripts/gpu-doom-gallery.sh run      on the GPU host, from the repo root (device tool: carry
#                                        [".gpu", ".peer"]); images in $OUT (or /tmp/doom-gallery)
#
# Then copy penumbra-e1m1.png and peer-e1m1.png into docs/gallery/.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:-run}

# The side-by-side benchmark packs the same two programs.
[ "$mode" = pack ] && exec scripts/gpu-bench-vs-seed.sh pack "${@:2}"

out=${OUT:-/tmp/doom-gallery}
mkdir -p "$out"
command -v penumbra >/dev/null || { echo "source .gpu/env.sh first" >&2; exit 2; }
width=${WIDTH:-1280} height=${HEIGHT:-800} spp=${SPP:-4096}

# The peer at its defaults (4 spp a frame, 3 bounces, temporal accumulation, denoiser); 600
# frames of a still camera is 2400 samples a pixel in its history.
bash .peer/run.sh --width "$width" --height "$height" --frames "${PEER_FRAMES:-600}" \
  --screenshot "$out/peer-e1m1.png" > "$out/peer-e1m1.json" 2> "$out/peer-e1m1.err"
wad=$(sed -n 's/^run.sh: the map it renders: //p' "$out/peer-e1m1.err" | tail -1)
[ -f "$wad" ] || { echo "the peer did not say where DOOM1.WAD is (see $out/peer-e1m1.err)" >&2; exit 1; }

# Player 1 starts at map (1056, -3616) facing north (angle 90) on a floor at height 0: scene
# (33, 0, 113) looking along -z; the peer's eye is 56 units (1.75 m) up.
# shellcheck disable=SC2086  # PENUMBRA_FLAGS is split into options on purpose
penumbra render "$wad" --map E1M1 --torch 0 --camera 33,1.75,113 --look-at 33,1.75,112 --fov 90 \
  --width "$width" --height "$height" --spp "$spp" -o "$out/penumbra-e1m1.png" ${PENUMBRA_FLAGS:-}
# The same with Penumbra's own player view (eye at 41 units, 70 degrees), for docs/SCENES.md.
# shellcheck disable=SC2086
penumbra render "$wad" --map E1M1 --torch 0 --width "$width" --height "$height" --spp "$spp" \
  -o "$out/penumbra-e1m1-player-view.png" ${PENUMBRA_FLAGS:-}
ls -l "$out"

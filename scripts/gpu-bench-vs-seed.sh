#!/usr/bin/env bash
# The WebGPU Doom renderer (../shared/peers/seed-webgpu) and Penumbra on the same GPU, the same map
# (id's DOOM1.WAD, E1M1, from the player start) and the same settings, in one command; prints one
# table and keeps every JSON.
#
#   scripts/gpu-bench-vs-seed.sh pack     here: packs build/penumbra (.gpu/) and the peer (.peer/)
#   scripts/gpu-bench-vs-seed.sh run      on the GPU host, from the repo root (device tool: carry
#                                         [".gpu", ".peer"]); results in $OUT (or /tmp/vs-seed)
#
# Settings compared: the peer's defaults (1280x800, 4 spp, 3 bounces, temporal, denoise) with
# Penumbra's 5 a-trous passes and the peer at its default and at 5 passes; then 1920x1080, 1 spp,
# 4 bounces. Penumbra renders the WAD as it ships (its torch on, as for every WAD level) unless
# PENUMBRA_FLAGS says otherwise (e.g. PENUMBRA_FLAGS="--torch 0").
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:-run}
frames=${FRAMES:-200}

if [ "$mode" = pack ]; then
  [ -d ../shared/peers/seed-webgpu ] || {
    echo "gpu-bench-vs-seed: the WebGPU renderer (../shared/peers/seed-webgpu) is not beside this checkout;" \
         "a plain clone has no peer to compare with" >&2; exit 2; }
  scripts/gpu-pack.sh build/penumbra "${@:2}"
  rm -rf .peer && mkdir -p .peer && cp -r ../shared/peers/seed-webgpu/. .peer/
  grep -qx '/.peer/' .git/info/exclude || echo '/.peer/' >> .git/info/exclude
  du -sh .gpu .peer
  exit 0
fi

out=${OUT:-/tmp/vs-seed}
mkdir -p "$out"
command -v penumbra >/dev/null || { echo "source .gpu/env.sh first" >&2; exit 2; }

peer() {  # peer NAME ARGS...: the peer's JSON into $out/peer-NAME.json
  local name=$1; shift
  bash .peer/run.sh --frames "$frames" "$@" > "$out/peer-$name.json" 2> "$out/peer-$name.err"
}
penumbra_viewer() {  # penumbra_viewer NAME ARGS...
  local name=$1; shift
  # shellcheck disable=SC2086
  penumbra bench "$wad" --map E1M1 --viewer --frames "$frames" --json ${PENUMBRA_FLAGS:-} "$@" > "$out/penumbra-$name.json"
}

peer default
wad=$(sed -n 's/^run.sh: the map it renders: //p' "$out/peer-default.err" | tail -1)
[ -f "$wad" ] || { echo "the peer did not say where DOOM1.WAD is (see $out/peer-default.err)" >&2; exit 1; }
peer default-5pass --denoise-passes 5
peer 1080 --width 1920 --height 1080 --spp 1 --bounces 4
penumbra_viewer default --width 1280 --height 800 --spp 4 --bounces 3 --denoise 5
penumbra_viewer 1080 --width 1920 --height 1080 --spp 1 --bounces 4 --denoise 5

# One table, read with the peer's own bundled node (the GPU host may have no python or jq).
node="$(dirname "$(dirname "$(dirname "$wad")")")/bin/node"
"$node" - "$out" <<'JS'
const fs = require('fs');
const out = process.argv[2];
const read = (f) => JSON.parse(fs.readFileSync(`${out}/${f}`, 'utf8'));
const rows = [
  ['1280x800, 4 spp, 3 bounces (peer: its 1 a-trous pass)', 'peer-default.json', 'penumbra-default.json'],
  ['1280x800, 4 spp, 3 bounces (both 5 a-trous passes)', 'peer-default-5pass.json', 'penumbra-default.json'],
  ['1920x1080, 1 spp, 4 bounces', 'peer-1080.json', 'penumbra-1080.json'],
];
const pad = (s, n) => String(s).padEnd(n);
console.log(pad('setting', 56) + pad('peer trace', 12) + pad('peer frame', 12) + pad('ours trace', 12) +
            pad('ours frame', 12) + 'frame ratio');
for (const [label, p, q] of rows) {
  const a = read(p), b = read(q);
  const peerFrame = a.gpu_frame_span_ms.median, ours = b.viewer_frame_ms;
  console.log(pad(label, 56) + pad(a.pathtrace_ms.median.toFixed(2), 12) + pad(peerFrame.toFixed(2), 12) +
              pad(b.passes.trace.toFixed(2), 12) + pad(ours.toFixed(2), 12) + (peerFrame / ours).toFixed(2));
}
console.log('(GPU timestamps, medians; frame = the whole GPU frame span; ratio = peer / penumbra, above 1 ' +
            'Penumbra is faster. The peer\'s wall-clock frame at its defaults: ' +
            read('peer-default.json').frame_ms.median.toFixed(2) + ' ms.)');
JS

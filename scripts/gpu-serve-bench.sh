#!/usr/bin/env bash
# `penumbra serve` on the GPU host, watched by headless clients on the same host (serve-probe; no
# browser there), at the WebGPU renderer's settings (DOOM1.WAD E1M1, 1280x800, 4 spp, 3 bounces,
# temporal + denoise). Records frames per second delivered, bytes per frame, Mbit/s,
# input-to-frame latency and encoding time, saves a few received frames as PNG, and runs the
# WebGPU renderer's own benchmark in the same call (docs/PERFORMANCE.md wants both figures).
#
#   scripts/gpu-serve-bench.sh pack     here: packs build/penumbra and build/serve-probe (.gpu/,
#                                       bin and lib xz-compressed to fit the 64 MiB carry) and
#                                       the peer (.peer/)
#   scripts/gpu-serve-bench.sh run      on the GPU host from the repo root (device tool: carry
#                                       [".gpu", ".peer"]); results in $OUT (or /tmp/serve-bench)
# SECONDS_EACH (default 15) sets how long each probe watches.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:-run}
each=${SECONDS_EACH:-15}

if [ "$mode" = pack ]; then
  rm -rf .gpu  # what another pack left there (test binaries, layers) would not fit beside the peer
  scripts/gpu-bench-vs-seed.sh pack build/serve-probe  # .gpu/ with both programs, and .peer/
  tar -C .gpu -cf - bin lib | xz -T0 -6 > .gpu/payload.tar.xz
  rm -rf .gpu/bin .gpu/lib
  du -sh .gpu .peer
  exit 0
fi

out=${OUT:-/tmp/serve-bench}
mkdir -p "$out/frames"
if ! command -v penumbra >/dev/null; then
  [ -f .gpu/payload.tar.xz ] && xz -dc .gpu/payload.tar.xz | tar -C .gpu -x
  # shellcheck disable=SC1091
  source .gpu/env.sh
fi
penumbra info > "$out/info.txt" 2>&1 || true

# The WebGPU renderer at its defaults (and where its DOOM1.WAD is).
bash .peer/run.sh --frames 200 > "$out/peer-default.json" 2> "$out/peer-default.err"
wad=$(sed -n 's/^run.sh: the map it renders: //p' "$out/peer-default.err" | tail -1)
[ -f "$wad" ] || { echo "the peer did not say where DOOM1.WAD is (see $out/peer-default.err)" >&2; exit 1; }
settings=(--map E1M1 --width 1280 --height 800 --spp 4 --bounces 3 --denoise)
penumbra bench "$wad" --map E1M1 --viewer --frames 200 --json --width 1280 --height 800 --spp 4 --bounces 3 --denoise 5 > "$out/bench-viewer.json"

serve() {  # serve NAME SERVE_ARGS... -- PROBE_ARGS...: one server, one probe run, both logs kept
  local name=$1; shift
  local serve_args=() probe_args=()
  while [ $# -gt 0 ] && [ "$1" != -- ]; do serve_args+=("$1"); shift; done
  [ $# -gt 0 ] && shift
  probe_args=("$@")
  penumbra serve "$wad" "${settings[@]}" --port 0 "${serve_args[@]}" > "$out/serve-$name.out" 2> "$out/serve-$name.err" &
  local pid=$! port=""
  for _ in $(seq 1 600); do
    port=$(sed -n 's#^penumbra: serving http://127.0.0.1:\([0-9]*\)/.*#\1#p' "$out/serve-$name.out")
    [ -n "$port" ] && break
    kill -0 $pid 2>/dev/null || break
    sleep 0.1
  done
  [ -n "$port" ] || { echo "serve $name did not start (see $out/serve-$name.err)" >&2; kill $pid 2>/dev/null; return 1; }
  serve-probe --port "$port" --pid "$pid" "${probe_args[@]}" > "$out/probe-$name.json" || true
  kill -TERM $pid; wait $pid || true
}

# Warm up once (pipelines, clocks), then measure.
serve warmup --max-fps 0 --rest-fps 0 -- --seconds 5
serve unlimited --max-fps 0 --rest-fps 0 -- --seconds "$each" --input-every 0.1 --save "$out/frames" --save-count 4
serve fps60-moving --max-fps 60 -- --seconds "$each" --input-every 0.02
serve rest --max-fps 60 -- --seconds "$each" --input-every 0
serve clients8 --max-fps 60 -- --seconds "$each" --clients 8 --input-every 0.25
# The load test's shape on the GPU: eight browsers for a minute, the server's memory sampled.
[ "${LOAD_SECONDS:-60}" -gt 0 ] && serve load --max-fps 60 -- --seconds "${LOAD_SECONDS:-60}" --clients 8 --input-every 0.1

for f in "$out"/probe-*.json; do
  echo "== $(basename "$f")"
  grep -E '"(fps|mbits|bytesPerFrame|latencyMsMedian|latencyMsP95|encodeMsMedian|encodeMsP95|encodeMsMax|renderMsMedian|quality|error)"' "$f" | head -11
  tr -d ' \n' < "$f" | grep -o '"serverRssKiB":\[[0-9,]*\]' || true
done
grep -o '"viewer_frame_ms": *[0-9.]*' "$out/bench-viewer.json" || true
grep -o '"median": *[0-9.]*' "$out/peer-default.json" | head -3 || true

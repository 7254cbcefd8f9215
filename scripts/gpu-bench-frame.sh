#!/usr/bin/env bash
# The viewer's whole frame and the error at equal time, for every scene docs/PERFORMANCE.md
# tracks, for one or more builds side by side (a build from before a change and one after).
#
#   scripts/gpu-bench-frame.sh pack [EXTRA_BINARY...]   here: build/penumbra (+ extra builds,
#                                 e.g. an older one renamed penumbra-base) into .gpu/, and the
#                                 real assets, compressed, into .assets/ (never committed)
#   scripts/gpu-bench-frame.sh run                      on the GPU host from the repo root, after
#                                 `source .gpu/env.sh` (device tool: carry [".gpu", ".assets"])
#
# Environment for `run`: BINARIES (default "penumbra"), SCENES (default: all below), OUT, and
# VIEWER_FLAGS (extra `bench --viewer` options for both figures, e.g. "--roulette-start 3").
# Per build and scene it writes $OUT/<build>-<scene>-frame.json (1920x1080, 1 spp, 4 bounces,
# temporal + 5 a-trous passes) and $OUT/<build>-<scene>-error.json: the relative MSE against the
# build's own 2048-spp reference after ERROR_BUDGET_MS (default 30) of GPU frame time at 480x270,
# raw (the temporal running mean) and denoised, means of ERROR_TRIALS (default 8) runs from a
# fresh history each (one run's error is heavy-tailed: a late firefly can double it). Each build
# is compared with its own converged image, so the figures measure noise, not the bias of an
# older build.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:-run}

if [ "$mode" = pack ]; then
  scripts/gpu-pack.sh build/penumbra "${@:2}"
  mkdir -p .assets
  grep -qx '/.assets/' .git/info/exclude || echo '/.assets/' >> .git/info/exclude
  xz -T2 -6 -c /usr/share/games/doom/freedoom1.wad > .assets/freedoom1.wad.xz
  xz -T2 -6 -c /usr/share/glmark2/models/bunny.obj > .assets/bunny.obj.xz
  cp /usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb .assets/
  # id's DOOM1.WAD comes from the WebGPU renderer's payload beside the checkout; a plain clone lacks
  # it, and the DOOM1 scenes are then skipped on the host.
  if [ -f ../shared/peers/seed-webgpu/payload.tar.xz ]; then
    tar -xJOf ../shared/peers/seed-webgpu/payload.tar.xz app/wads/DOOM1.WAD | xz -T2 -6 -c > .assets/DOOM1.WAD.xz
  else
    echo "gpu-bench-frame: no ../shared/peers/seed-webgpu/payload.tar.xz: DOOM1.WAD not packed, its scenes will skip" >&2
  fi
  du -sh .gpu .assets
  exit 0
fi

out=${OUT:-/tmp/frame-bench}
mkdir -p "$out"
# The assets where the scenes and tests expect them; a scene whose asset was not carried is
# skipped (DOOM1_WAD may name a copy already on the host, e.g. the one inside the peer's payload).
unpack() {  # unpack PACKED TARGET: .xz files are decompressed, others copied
  [ -f "$1" ] || return 0
  mkdir -p "$(dirname "$2")"
  case "$1" in *.xz) xz -dc "$1" > "$2" ;; *) cp "$1" "$2" ;; esac
}
unpack .assets/freedoom1.wad.xz /usr/share/games/doom/freedoom1.wad
unpack .assets/bunny.obj.xz /usr/share/glmark2/models/bunny.obj
unpack .assets/2CylinderEngine.glb /usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
doom1=${DOOM1_WAD:-/tmp/DOOM1.WAD}
[ -n "${DOOM1_WAD:-}" ] || unpack .assets/DOOM1.WAD.xz "$doom1"

declare -A scene=(
  [cornell]="cornell"
  [freedoom-e1m1]="/usr/share/games/doom/freedoom1.wad --map E1M1"
  [doom1-e1m1]="$doom1 --map E1M1"
  [bunny-cornell]="scenes/bunny-cornell.json"
  [bunny-room]="bunny-room"
  [materials]="materials"
  [caffeine]="caffeine"
  [engine]="scenes/engine.json"
)
budget=${ERROR_BUDGET_MS:-30}
trials=${ERROR_TRIALS:-8}
# ERROR_FRAMES=N: N frames per trial instead of the time budget, after a fixed warm-up, so builds
# that differ only after the trace (the denoiser) filter the very same images.
if [ -n "${ERROR_FRAMES:-}" ]; then
  budgetFlag="--budget-frames $ERROR_FRAMES" warmup="--warmup-seconds 0 --warmup-frames 10"
else
  budgetFlag="--budget-ms $budget" warmup="--warmup-seconds 0.5"
fi
for bin in ${BINARIES:-penumbra}; do
  for name in ${SCENES:-cornell freedoom-e1m1 doom1-e1m1 bunny-cornell bunny-room materials caffeine engine}; do
    s=${scene[$name]}
    asset=${s%% *}
    case "$asset" in /*) [ -f "$asset" ] || { echo "$name: $asset was not carried, skipped" >&2; continue; } ;; esac
    # shellcheck disable=SC2086
    "$bin" bench $s --viewer --width 1920 --height 1080 --spp 1 --bounces 4 --denoise 5 --frames 100 --json ${VIEWER_FLAGS:-} \
      > "$out/$bin-$name-frame.json" 2> "$out/$bin-$name-frame.err" || echo "$bin $name: frame bench failed" >&2
    # shellcheck disable=SC2086
    "$bin" render $s --width 480 --height 270 --spp 2048 --bounces 4 --quiet -o "$out/$bin-$name-ref.exr" \
      2> "$out/$bin-$name-ref.err" || echo "$bin $name: reference failed" >&2
    # shellcheck disable=SC2086
    "$bin" bench $s --viewer --width 480 --height 270 --spp 1 --bounces 4 --denoise 5 --frames 10 \
      $warmup --reference "$out/$bin-$name-ref.exr" $budgetFlag --error-trials "$trials" \
      --json ${VIEWER_FLAGS:-} \
      > "$out/$bin-$name-error.json" 2> "$out/$bin-$name-error.err" || echo "$bin $name: error bench failed" >&2
    rm -f "$out/$bin-$name-ref.exr"
  done
done

# One table from the JSON files (one key per line, as penumbra prints them).
val() { grep -o "\"$2\": [0-9.e+-]*" "$1" 2>/dev/null | head -1 | sed 's/.*: //'; }
printf '%-16s %-14s %10s %10s %10s %8s %12s %12s %12s\n' scene build frame_ms trace_ms denoise rays/px/spp frames@T relMSE_raw relMSE_denoised
for name in ${SCENES:-cornell freedoom-e1m1 doom1-e1m1 bunny-cornell bunny-room materials caffeine engine}; do
  for bin in ${BINARIES:-penumbra}; do
    f="$out/$bin-$name-frame.json" e="$out/$bin-$name-error.json"
    printf '%-16s %-14s %10s %10s %10s %8s %12s %12s %12s\n' "$name" "$bin" "$(val "$f" viewer_frame_ms)" \
      "$(val "$f" trace)" "$(val "$f" denoise)" "$(val "$f" rays_per_pixel_per_sample)" "$(val "$e" budget_frames)" \
      "$(val "$e" rel_mse_raw)" "$(val "$e" rel_mse_denoised)"
  done
done
echo "(frame: 1920x1080, 1 spp, 4 bounces, temporal + 5 a-trous passes, GPU ms; error: 480x270 after $budget ms of GPU frames, raw and denoised, against the build's own 2048-spp reference, means of $trials trials)"

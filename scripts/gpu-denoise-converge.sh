#!/usr/bin/env bash
# Issue 39: does the viewer's denoised image converge at rest, and keep its gain in motion? At the
# WebGPU renderer's settings (DOOM1 E1M1, 1280x800, 4 spp, 3 bounces, torch off), relative MSE
# against a converged render of the same view, raw (the temporal mean) and denoised, for the
# blended output and the a-trous filter alone (--denoise-filter-only: the filter before issue 39):
#   rest 30 and rest 64: 30 / 64 still frames from a fresh history (the target: denoised <= raw);
#   one frame: a single frame from a fresh history (the filter's gain in motion);
#   walk 16: 16 frames walking (bench --error-camera-motion walk) that end on the reference's view.
#
#   scripts/gpu-bench-frame.sh pack                here (packs build/penumbra and DOOM1.WAD)
#   scripts/gpu-denoise-converge.sh                on the GPU host, after `source .gpu/env.sh`
#
# Environment: OUT (default /tmp/denoise-converge), REF_SPP (default 16384), TRIALS (default 8),
# SCENE (default the DOOM1.WAD unpacked by gpu-bench-frame.sh's layout: .assets/DOOM1.WAD.xz).
set -euo pipefail
cd "$(dirname "$0")/.."
out=${OUT:-/tmp/denoise-converge}
mkdir -p "$out"
doom1=${DOOM1_WAD:-/tmp/DOOM1.WAD}
[ -f "$doom1" ] || xz -dc .assets/DOOM1.WAD.xz > "$doom1"
scene=${SCENE:-"$doom1 --map E1M1"}
size="--width 1280 --height 800"
trials=${TRIALS:-8}
# shellcheck disable=SC2086
penumbra render $scene $size --spp "${REF_SPP:-16384}" --bounces 3 --torch 0 --quiet -o "$out/ref.exr"
val() { grep -o "\"$2\": [0-9.e+-]*" "$1" | head -1 | sed 's/.*: //'; }
printf '%-10s %-12s %12s %12s\n' case filter relMSE_raw relMSE_denoised
for c in "rest-30:--budget-frames 30" "rest-64:--budget-frames 64" "one-frame:--budget-frames 1" \
         "walk-16:--budget-frames 16 --error-camera-motion walk"; do
  name=${c%%:*} flags=${c#*:}
  for filter in blended filter-only; do
    extra=""; [ "$filter" = filter-only ] && extra="--denoise-filter-only"
    f="$out/$name-$filter.json"
    # shellcheck disable=SC2086
    penumbra bench $scene --viewer $size --spp 4 --bounces 3 --torch 0 --denoise 5 --frames 10 --warmup-seconds 0.5 \
      --reference "$out/ref.exr" $flags --error-trials "$trials" $extra --json > "$f"
    printf '%-10s %-12s %12s %12s\n' "$name" "$filter" "$(val "$f" rel_mse_raw)" "$(val "$f" rel_mse_denoised)"
  done
done
echo "(DOOM1 E1M1 1280x800, 4 spp, 3 bounces, torch off; against a ${REF_SPP:-16384}-spp render; means of $trials trials)"

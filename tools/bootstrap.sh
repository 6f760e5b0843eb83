#!/usr/bin/env bash
# Idempotent set-up for the cluster-dynamics plugin on Debian 12:
#   1. Debian packages (compilers, Open MPI, GoogleTest, python3-pytest/numpy/matplotlib/sfepy,
#      python3-sphinx for the doc build, OpenCL with pocl for the GPU package on the CPU)
#   2. the LAMMPS 4Feb2025 source (Debian's source package, checksum pinned)
#   3. LAMMPS built as a shared library + lmp, cached under ~/.cache (reused by later runs)
#   4. the plugin (build/clusterdynplugin.so) and build/env.sh
#   5. with the pinned source (no override below): a second, small LAMMPS (core, PLUGIN, GPU
#      in double precision) and the plugin built against it (build/gpu-double/): the /gpu
#      styles' double-precision check, which the tests skip without it
# Overrides (see doc/Build.rst):
#   CLUSTERDYN_LAMMPS_SOURCE=/path/to/lammps  build that LAMMPS source tree instead of the
#                                             pinned one (same configuration, own cache entry)
#   CLUSTERDYN_LAMMPS_BUILD=/path/to/build    use an existing CMake build of that tree (with
#                                             liblammps.so, lmp, PLUGIN, MPI) as it is
#   CLUSTERDYN_CACHE=/path             cache folder (default ~/.cache/clusterdyn)
#   CLUSTERDYN_BUILD_DIR=/path         the plugin's build folder (default build/ of this tree;
#                                      tools/check_lammps_version.sh uses one per version)
set -euo pipefail

top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cache=${CLUSTERDYN_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/clusterdyn}
plugin_bld=${CLUSTERDYN_BUILD_DIR:-$top/build}
jobs=$(nproc)

lammps_version=20250204
lammps_debver=20250204+dfsg.1-2
lammps_tarball=lammps_20250204+dfsg.1.orig.tar.xz
lammps_sha256=3671165bd52fad36734e0a9136c5bc5ecb225e03988f8c89aa13366a8b53b1c7

apt_packages=(build-essential cmake ninja-build pkg-config xz-utils dpkg-dev ca-certificates
  libopenmpi-dev openmpi-bin libgtest-dev libeigen3-dev
  python3 python3-pytest python3-numpy python3-matplotlib python3-mpi4py python3-sfepy python3-sphinx
  ocl-icd-opencl-dev opencl-headers pocl-opencl-icd clinfo)

# LAMMPS configuration: changing it changes the cache key
lammps_cmake_opts=(-DCMAKE_BUILD_TYPE=Release -DBUILD_SHARED_LIBS=on -DBUILD_MPI=on -DBUILD_OMP=on
  -DLAMMPS_EXCEPTIONS=on -DBUILD_TOOLS=off -DWITH_JPEG=off -DWITH_PNG=off -DWITH_FFMPEG=off
  -DWITH_GZIP=on -DPKG_PLUGIN=on -DPKG_OPENMP=on -DPKG_SHOCK=on -DPKG_EXTRA-PAIR=on
  -DPKG_EXTRA-COMPUTE=on -DPKG_EXTRA-FIX=on -DPKG_MOLECULE=on -DPKG_DPD-BASIC=on -DPKG_LEPTON=on
  -DPKG_BPM=on -DPKG_GRANULAR=on -DPKG_PERI=on -DPKG_OPT=on -DPKG_MACHDYN=on -DDOWNLOAD_EIGEN3=no
  -DPKG_GPU=on -DGPU_API=opencl -DGPU_PREC=mixed -DUSE_STATIC_OPENCL_LOADER=off
  -DCMAKE_CXX_FLAGS=-DGERYON_FORCE_SHARED_MAIN_MEM_OFF
  -DCMAKE_SKIP_INSTALL_RPATH=off -DCMAKE_BUILD_RPATH_USE_ORIGIN=on)
# the double-precision GPU build: only what the plugin needs (LAMMPS's core, PLUGIN) and GPU
lammps_double_opts=(-DCMAKE_BUILD_TYPE=Release -DBUILD_SHARED_LIBS=on -DBUILD_MPI=on
  -DBUILD_OMP=on -DLAMMPS_EXCEPTIONS=on -DBUILD_TOOLS=off -DWITH_JPEG=off -DWITH_PNG=off
  -DWITH_FFMPEG=off -DWITH_GZIP=on -DPKG_PLUGIN=on
  -DPKG_GPU=on -DGPU_API=opencl -DGPU_PREC=double -DUSE_STATIC_OPENCL_LOADER=off
  -DCMAKE_CXX_FLAGS=-DGERYON_FORCE_SHARED_MAIN_MEM_OFF
  -DCMAKE_SKIP_INSTALL_RPATH=off -DCMAKE_BUILD_RPATH_USE_ORIGIN=on)

say() { printf '[bootstrap] %s\n' "$*"; }
as_root() { if [ "$(id -u)" = 0 ]; then "$@"; else sudo "$@"; fi; }

install_packages() {
  local missing=()
  for p in "${apt_packages[@]}"; do
    [[ $(dpkg-query -W -f='${Status}' "$p" 2>/dev/null) == 'install ok installed' ]] || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return
  say "installing Debian packages: ${missing[*]}"
  as_root apt-get update -qq
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

fetch_lammps_source() {
  local dir=$cache/src
  local src=$dir/lammps-$lammps_version
  if [ -f "$src/cmake/CMakeLists.txt" ]; then echo "$src"; return; fi
  mkdir -p "$dir"
  if [ ! -f "$dir/$lammps_tarball" ]; then
    say "downloading the LAMMPS source package $lammps_debver (Debian trixie)" >&2
    local list=/etc/apt/sources.list.d/clusterdyn-trixie-src.sources
    if [ ! -f "$list" ]; then
      printf 'Types: deb-src\nURIs: http://deb.debian.org/debian\nSuites: trixie\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
        | as_root tee "$list" >/dev/null
    fi
    as_root apt-get update -qq >&2
    (cd "$dir" && apt-get source --download-only --tar-only "lammps=$lammps_debver" >&2)
  fi
  echo "$lammps_sha256  $dir/$lammps_tarball" | sha256sum -c --quiet - >&2 \
    || { say "checksum mismatch for $dir/$lammps_tarball" >&2; exit 1; }
  rm -rf "$src.tmp" && mkdir -p "$src.tmp"
  tar -xJf "$dir/$lammps_tarball" -C "$src.tmp" --strip-components=1
  mv "$src.tmp" "$src"
  echo "$src"
}

version_of() {  # $1 = source tree; prints its version as YYYYMMDD (from src/version.h)
  local v
  v=$(sed -n 's/^#define LAMMPS_VERSION "\(.*\)"/\1/p' "$1/src/version.h" 2>/dev/null)
  date -d "$v" +%Y%m%d 2>/dev/null || { say "no LAMMPS version in $1/src/version.h" >&2; exit 1; }
}

build_lammps() {  # $1 = source tree, $2.. = its CMake options; prints the build folder
  local src=$1
  shift
  local opts=("$@")
  local key
  key=$(printf '%s\n' "$src" "${opts[@]}" | sha256sum | cut -c1-12)
  local ver
  ver=$(version_of "$src") || exit 1
  local bld=$cache/lammps-$ver-$key
  if [ -f "$bld/.complete" ]; then echo "$bld"; return; fi
  say "building LAMMPS in $bld (several minutes on 2 cores)" >&2
  mkdir -p "$cache"
  cmake -S "$src/cmake" -B "$bld" -G Ninja "${opts[@]}" >"$bld.configure.log" 2>&1 \
    || { tail -30 "$bld.configure.log" >&2; exit 1; }
  cmake --build "$bld" -j "$jobs" >"$bld.build.log" 2>&1 || { tail -40 "$bld.build.log" >&2; exit 1; }
  touch "$bld/.complete"
  echo "$bld"
}

install_packages
if [ -n "${CLUSTERDYN_LAMMPS_BUILD:-}" ]; then
  lmp_src=${CLUSTERDYN_LAMMPS_SOURCE:?CLUSTERDYN_LAMMPS_BUILD needs CLUSTERDYN_LAMMPS_SOURCE (its source tree)}
  lmp_bld=$CLUSTERDYN_LAMMPS_BUILD
else
  lmp_src=${CLUSTERDYN_LAMMPS_SOURCE:-$(fetch_lammps_source)}
  lmp_bld=$(build_lammps "$lmp_src" "${lammps_cmake_opts[@]}")
fi
lmp_double=
if [ -z "${CLUSTERDYN_LAMMPS_BUILD:-}${CLUSTERDYN_LAMMPS_SOURCE:-}" ]; then
  lmp_double=$(build_lammps "$lmp_src" "${lammps_double_opts[@]}")
fi
[ -x "$lmp_bld/lmp" ] && [ -e "$lmp_bld/liblammps.so" ] \
  || { say "no lmp / liblammps.so in $lmp_bld"; exit 1; }
# lmp must run the liblammps it was built with (Debian's liblammps.so.0 has the same soname)
# (ldd's output is read whole: `ldd | grep -q` under pipefail fails when grep exits first)
lmp_libs=$(ldd "$lmp_bld/lmp")
[[ $lmp_libs == *"liblammps.so.0 => $lmp_bld/"* ]] \
  || { say "$lmp_bld/lmp does not load its own liblammps.so.0:"; grep lammps <<<"$lmp_libs"; exit 1; }

# the plugin against the double-precision GPU build (its files only, for the tests)
double_bld=
if [ -n "$lmp_double" ]; then
  double_bld=$plugin_bld/gpu-double
  mkdir -p "$double_bld"
  if [ ! -f "$double_bld/build.ninja" ] || ! grep -qs "LAMMPS_BUILD_DIR:PATH=$lmp_double\$" "$double_bld/CMakeCache.txt"; then
    cmake -S "$top" -B "$double_bld" -G Ninja -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=off \
      -DLAMMPS_ROOT="$lmp_src" -DLAMMPS_BUILD_DIR="$lmp_double" >"$double_bld/configure.log" 2>&1 \
      || { tail -30 "$double_bld/configure.log"; exit 1; }
  fi
fi

# the plugin: reconfigure only when a LAMMPS build changed
mkdir -p "$plugin_bld"
if [ ! -f "$plugin_bld/build.ninja" ] || ! grep -qs "LAMMPS_BUILD_DIR:PATH=$lmp_bld\$" "$plugin_bld/CMakeCache.txt" \
   || ! grep -qs "CLUSTERDYN_GPU_DOUBLE_DIR:PATH=$double_bld\$" "$plugin_bld/CMakeCache.txt"; then
  cmake -S "$top" -B "$plugin_bld" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DLAMMPS_ROOT="$lmp_src" -DLAMMPS_BUILD_DIR="$lmp_bld" \
    -DCLUSTERDYN_GPU_DOUBLE_DIR="$double_bld" -DCLUSTERDYN_GPU_DOUBLE_LAMMPS="$lmp_double" \
    >"$plugin_bld/configure.log" 2>&1 || { tail -30 "$plugin_bld/configure.log"; exit 1; }
fi
if [ -n "$double_bld" ]; then
  cmake --build "$double_bld" -j "$jobs" --target clusterdynplugin >"$double_bld/build.log" 2>&1 \
    || { tail -40 "$double_bld/build.log"; exit 1; }
fi
cmake --build "$plugin_bld" -j "$jobs" >"$plugin_bld/build.log" 2>&1 || { tail -40 "$plugin_bld/build.log"; exit 1; }
say "ready: source $plugin_bld/env.sh"

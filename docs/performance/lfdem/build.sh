#!/bin/bash
# Build LF_DEM (ryseto/LF_DEM) on Debian 12 from a source tree obtained by any means.
#
#   build.sh LF_DEM_SOURCE_TREE [COMMIT]
#
# LF_DEM_SOURCE_TREE is the top of the repository (the folder holding LF_DEM/Makefile).
# The commit is taken from `git rev-parse HEAD` if the tree is a git work tree,
# else from the second argument, else from the file LF_DEM_SOURCE_TREE/COMMIT
# (write it when exporting with `git archive`), else "unknown".
#
# Installs (as root, Debian packages only):
#   g++ make libsuitesparse-dev (CHOLMOD 5.12 with METIS) and
#   libopenblas-serial-dev (single-threaded OpenBLAS; CHOLMOD's supernodal
#   factorisation spends its time in BLAS, and the serial build never starts threads).
# LF_DEM is linked (with --no-as-needed and a runpath) against the BLAS and LAPACK of
# the serial OpenBLAS folder, so it uses the serial OpenBLAS whatever the system's
# libblas.so.3/liblapack.so.3 alternatives point to (checked at the end with LD_DEBUG).
# LF_DEM is compiled with the instruction-set flags our code is built with,
# WSF_ARCH_FLAGS (etc/bashrc; -march=native unless set), so that both codes
# run the same instructions: set WSF_ARCH_FLAGS= to build both for any x86-64.
# The binary is LF_DEM_SOURCE_TREE/LF_DEM/LF_DEM.
set -euo pipefail
arch=${WSF_ARCH_FLAGS--march=native}

src=${1:?usage: build.sh LF_DEM_SOURCE_TREE [COMMIT]}
src=$(cd "$src" && pwd)
[ -f "$src/LF_DEM/Makefile" ] || { echo "no LF_DEM/Makefile under $src" >&2; exit 1; }

if git -C "$src" rev-parse --verify -q HEAD >/dev/null 2>&1; then
    commit=$(git -C "$src" rev-parse HEAD)
elif [ -n "${2:-}" ]; then
    commit=$2
elif [ -f "$src/COMMIT" ]; then
    commit=$(head -1 "$src/COMMIT")
else
    commit=unknown
fi

pkgs="g++ make libsuitesparse-dev libopenblas-serial-dev"
missing=""
for p in $pkgs; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing="$missing $p"
done
if [ -n "$missing" ]; then
    [ "$(id -u)" = 0 ] || { echo "need root to install:$missing" >&2; exit 1; }
    apt-get update
    DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends $missing
fi

ob=/usr/lib/$(dpkg-architecture -qDEB_HOST_MULTIARCH 2>/dev/null || gcc -print-multiarch)/openblas-serial
[ -f "$ob/libblas.so" ] || { echo "serial OpenBLAS not found in $ob" >&2; exit 1; }

# LF_DEM reads its build settings from LF_DEM/config/Makefile_config.mk
# (made from config/Makefile_config_Ubuntu_OpenBLAS.mk, Debian paths).
cat > "$src/LF_DEM/config/Makefile_config.mk" <<EOF
DSFMT_RNG = no
UseMetis = no
install_dir = ~/bin/
CXX = g++
override_default_cholmod = true
Cholmod_path = -I /usr/include/suitesparse
Cholmod_Linking_Flags = -lcholmod
CXXFLAGS_EXTRA = -DGIT_VERSION='"$commit"' $arch
Lapack_Linking_Flags = -L$ob -Wl,-rpath,$ob -Wl,--no-as-needed -llapack
Blas_Linking_Flags = -lblas
Extra_Linking_Flags =
EOF

cd "$src/LF_DEM"
make clean >/dev/null
# Makefile default target: -O3 -Wall -std=c++11 (+ CXXFLAGS_EXTRA)
if ! make -j"${JOBS:-1}" all > build.log 2>&1; then tail -40 build.log >&2; echo "LF_DEM did not build (log: $src/LF_DEM/build.log)" >&2; exit 1; fi
echo "compile lines:"; grep -E '^g\+\+' build.log | sed -n '1p;$p'
echo "warnings: $(grep -c 'warning:' build.log || true) (log: $src/LF_DEM/build.log)"
[ -x LF_DEM ] || { echo "LF_DEM did not build" >&2; exit 1; }

echo "LF_DEM commit: $commit"
echo "binary: $src/LF_DEM/LF_DEM"
echo "compiler: $(g++ --version | head -1), instruction set: ${arch:-x86-64}"
echo "packages: $(dpkg-query -W -f='${Package}=${Version} ' libsuitesparse-dev libcholmod3 libopenblas0-serial 2>/dev/null)"
echo "libraries loaded at run time:"
# (LF_DEM -h exits 1 after its usage: its status is not the build's)
{ LD_DEBUG=libs ./LF_DEM -h 2>&1 || true; } | grep 'calling init' \
    | grep -E 'blas|lapack|cholmod|gomp' | sed 's/.*calling init: /  /'

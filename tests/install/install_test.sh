#!/bin/sh
# Installs the build into a temporary prefix and builds a tiny C host against it both ways a
# host finds a library: find_package(Sheaf) with CMake, and pkg-config sheaf. Each host renders
# and saves an image from the installed copy (the image module found beside libsheaf).
#   install_test.sh BUILD_DIR SOURCE_DIR WORK_DIR CMAKE
set -eu
build=$1 src=$2 work=$3 cmake=$4
rm -rf "$work"
mkdir -p "$work"
# Somewhere other than where the build was configured to install: the files must relocate.
prefix=$work/prefix
"$cmake" --install "$build" --prefix "$prefix" >"$work/install.log"
lib=$(dirname "$(find "$prefix" -name 'libsheaf.so.0' | head -n 1)")
[ -f "$lib/libsheaf_image.so.0" ] || { echo "no image module beside $lib/libsheaf.so.0"; exit 1; }

echo "== find_package(Sheaf)"
"$cmake" -S "$src/host" -B "$work/cmake-host" -DCMAKE_PREFIX_PATH="$prefix" >"$work/configure.log" ||
    { cat "$work/configure.log"; exit 1; }
grep "found Sheaf" "$work/configure.log"
"$cmake" --build "$work/cmake-host" >"$work/build.log" || { cat "$work/build.log"; exit 1; }
"$work/cmake-host/host" "$work/cmake-host.png" | tee "$work/cmake-host.out"
[ -s "$work/cmake-host.png" ]

echo "== pkg-config sheaf"
export PKG_CONFIG_PATH="$lib/pkgconfig"
echo "sheaf $(pkg-config --modversion sheaf): $(pkg-config --cflags --libs sheaf)"
# shellcheck disable=SC2046
cc -o "$work/pc-host" "$src/host/host.c" $(pkg-config --cflags --libs sheaf)
LD_LIBRARY_PATH=$(pkg-config --variable=libdir sheaf) "$work/pc-host" "$work/pc-host.png" |
    tee "$work/pc-host.out"
[ -s "$work/pc-host.png" ]
# The same frame both ways (the files' metadata hold each run's times, so the pixels are hashed).
a=$(sed -n 's/.*pixels //p' "$work/cmake-host.out") b=$(sed -n 's/.*pixels //p' "$work/pc-host.out")
[ -n "$a" ] && [ "$a" = "$b" ] || { echo "the hosts rendered different frames: $a, $b"; exit 1; }
echo "both hosts built, rendered the same frame and wrote it"

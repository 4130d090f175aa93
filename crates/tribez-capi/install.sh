#!/bin/sh
# Build the C library of tribez and install it under PREFIX (docs/c.md):
#
#     crates/tribez-capi/install.sh PREFIX [release|debug]     # default: release
#
# installs PREFIX/lib/libtribez.so, PREFIX/lib/libtribez.a, PREFIX/include/tribez.h and
# PREFIX/lib/pkgconfig/tribez.pc (from tribez.pc.in, with this PREFIX and the crates' version),
# so that `PKG_CONFIG_PATH=PREFIX/lib/pkgconfig pkg-config --cflags --libs tribez` works.
# CARGO_TARGET_DIR is honoured; cargo runs with --locked.
set -eu
if [ $# -lt 1 ] || [ $# -gt 2 ]; then
  echo "usage: $0 PREFIX [release|debug]" >&2
  exit 2
fi
profile=${2:-release}
case "$profile" in
  release) flag=--release ;;
  debug) flag= ;;
  *) echo "$0: profile must be release or debug, not $profile" >&2; exit 2 ;;
esac
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
mkdir -p "$1"
prefix=$(cd "$1" && pwd)
(cd "$root" && cargo build -p tribez-capi --locked $flag)
target=${CARGO_TARGET_DIR:-$root/target}
version=$(sed -n 's/^version = "\(.*\)"$/\1/p' "$root/Cargo.toml" | head -n 1)
mkdir -p "$prefix/lib/pkgconfig" "$prefix/include"
cp "$target/$profile/libtribez.so" "$target/$profile/libtribez.a" "$prefix/lib/"
cp "$here/include/tribez.h" "$prefix/include/"
sed -e "s|@PREFIX@|$prefix|g" -e "s|@VERSION@|$version|g" "$here/tribez.pc.in" \
  > "$prefix/lib/pkgconfig/tribez.pc"
echo "installed libtribez $version under $prefix (pkg-config: PKG_CONFIG_PATH=$prefix/lib/pkgconfig)"

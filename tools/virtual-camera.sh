#!/usr/bin/env bash
# Builds libgphoto2's own virtual PTP camera (libgphoto2_port/vusb: vcamera.c
# answers PTP as a Nikon D750) from Debian's libgphoto2 source package of the
# installed version, so that the DSLR path (camera::Gphoto2Camera over the
# ptp2 camera driver) runs in tests and CI without a camera. Debian builds
# the port library without it (--enable-vusb is off by default).
#
#   tools/virtual-camera.sh          build once per version, print the folder
#   eval "$(tools/virtual-camera.sh --env)"   and export IOLIBS to it
#
# The result is a folder of port drivers for IOLIBS: vusb.so, built here,
# beside links to Debian's own port drivers except usb1.so (the real USB
# driver would claim the "usb:" ports the virtual one answers on). The camera
# drivers (ptp2.so, CAMLIBS) stay Debian's own. Cached by version under
# ${ROCKFACE_CACHE:-~/.cache/rockface}/vcamera/libgphoto2-VERSION/iolibs;
# CMake looks there for the same version (tests/camera/vcamera). Nothing of
# libgphoto2 is copied into the repository.
#
# The virtual camera itself lives in the working folder of the program that
# opens it (docs/virtual-camera.md):
#   ./001,001      4 bytes, the D750's USB ids little-endian (b0 04 37 04):
#                  the vusb port "usb:001,001" reads them to match the model
#   ./vcamera/     the camera's card: vcamera/DCIM/100NIKON/*.JPG
# vcamera.c takes its folder from the compiled-in VCAMERADIR; built here as
# the relative path "vcamera", so every test has its own camera.
#
# Needs dpkg-dev (apt-get source), gcc, make, pkg-config, libexif-dev,
# libltdl-dev, patch (tools/setup.sh installs them) and, once, root to add a
# deb-src entry when apt has none.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)

version=$(dpkg-query -W -f='${Version}' libgphoto2-port12)
cache=${ROCKFACE_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/rockface}/vcamera/libgphoto2-$version
iolibs=$cache/iolibs
driverdir=$(pkg-config --variable=driverdir libgphoto2_port)

report() {
  if [ "${1:-}" = "--env" ]; then echo "export IOLIBS=$iolibs"; else echo "$iolibs"; fi
}

# The build is of this version with these patches: a patch changed since
# rebuilds it (the stamp holds the patches' checksum).
patches=("$repo"/tools/virtual-camera/*.patch)
stamp=$(cat "${patches[@]}" | sha256sum | cut -c1-16)
if [ -f "$iolibs/vusb.so" ] && [ "$(cat "$iolibs/patches.sha" 2> /dev/null)" = "$stamp" ]; then
  report "${1:-}"
  exit 0
fi

as_root=()
if [ "$(id -u)" -ne 0 ]; then as_root=(sudo); fi

# apt-get source needs a deb-src entry; Debian's image has only "deb". Add
# one for the same archive and suites (deb822 form, beside debian.sources).
if ! apt-cache showsrc libgphoto2 2>/dev/null | grep -qx "Version: $version"; then
  src_list=/etc/apt/sources.list.d/rockface-deb-src.sources
  echo "virtual-camera: adding $src_list (deb-src for apt-get source)" >&2
  if [ -f /etc/apt/sources.list.d/debian.sources ]; then
    sed 's/^Types: deb$/Types: deb-src/' /etc/apt/sources.list.d/debian.sources |
      "${as_root[@]}" tee "$src_list" > /dev/null
  else
    printf 'Types: deb-src\nURIs: http://deb.debian.org/debian\nSuites: %s\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
      "$(. /etc/os-release && echo "$VERSION_CODENAME")" | "${as_root[@]}" tee "$src_list" > /dev/null
  fi
  "${as_root[@]}" apt-get update -qq
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
echo "virtual-camera: building vusb.so from Debian's libgphoto2 $version in $work" >&2
# Debian's patches applied, as the installed libraries were built.
apt-get source -qq "libgphoto2=$version" > source.log 2>&1 || { cat source.log >&2; exit 1; }
src=$(find . -maxdepth 1 -type d -name 'libgphoto2-*' | head -1)
# Ours, in name order: vcamera-faults.patch (faults a test stages),
# vcamera-no-replay.patch (the port's id file is not a session to replay).
for p in "${patches[@]}"; do patch -d "$src" -p1 --quiet < "$p"; done

cd "$src/libgphoto2_port"
./configure --enable-vusb --disable-nls --quiet > "$work/configure.log" 2>&1 ||
  { tail -40 "$work/configure.log" >&2; exit 1; }
# Only vusb.so: linked against the installed libgphoto2_port (not the one of
# this tree), with the camera's folder relative to the working folder.
make -j "$(nproc)" vusb.la vcameradir=vcamera \
  iolib_libadd="$(pkg-config --libs libgphoto2_port)" > "$work/make.log" 2>&1 ||
  { tail -40 "$work/make.log" >&2; exit 1; }

# Assembled beside the cache and renamed into place: a half-built folder is
# never taken for a cached one.
mkdir -p "$cache"
staging=$(mktemp -d "$cache/iolibs.XXXXXX")
for driver in "$driverdir"/*.so; do
  [ "$(basename "$driver")" = usb1.so ] || ln -s "$driver" "$staging/"
done
cp .libs/vusb.so "$staging/vusb.so"
echo "$stamp" > "$staging/patches.sha"
rm -rf "$iolibs"
mv "$staging" "$iolibs"
chmod 755 "$iolibs"
echo "virtual-camera: built $iolibs/vusb.so" >&2
report "${1:-}"

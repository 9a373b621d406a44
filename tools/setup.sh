#!/usr/bin/env bash
# Installs the Debian 12 packages rockface needs to build and test, only
# those missing. Idempotent; run as root (or with sudo available).
set -euo pipefail

packages=(
  # toolchain
  g++ cmake ninja-build pkg-config
  # compiler cache: CI runs on the session's machine, which keeps ~/.cache
  ccache
  # libraries (DESIGN.md: Eigen, OpenCV, libgphoto2, SQLite; header-only helpers)
  libeigen3-dev libopencv-dev libgphoto2-dev libexif-dev libsqlite3-dev nlohmann-json3-dev libcli11-dev
  # OpenCV's contrib modules: ximgproc's thinning for trace proposals (issue 25)
  libopencv-contrib-dev
  # tablet UI: Dear ImGui 1.86 (with its OpenGL 3 backend source and stb),
  # EGL + GLES 3 headers and libraries, Mesa's EGL (surfaceless platform) and
  # software renderer for headless runs, Xlib and XInput 2 (multi-touch) for
  # the window, a TTF font
  libimgui-dev libstb-dev libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri libx11-dev libxi-dev
  fonts-dejavu-core
  # the UI's window test: a virtual X server
  xvfb xauth
  # the block's motion after failure: Boost.Odeint (header-only, in libboost-dev)
  libboost-dev
  # the field report's PDF (cairo's PDF surface)
  libcairo2-dev
  # tests and benchmarks
  libgtest-dev libgmock-dev libbenchmark-dev
  # the report tests read the PDF back (pdftotext, pdftoppm)
  poppler-utils
  # the office server (issue 24): libpq's C API, OpenSSL's SHA-256, and for
  # the tests a real PostgreSQL server (initdb, pg_ctl) and openssl to make
  # the TLS test's CA and certificate
  libpq-dev libssl-dev postgresql openssl
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

as_root=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then as_root=(sudo); else
    echo "setup: missing packages (${missing[*]}) and not root: run as root or install sudo" >&2
    exit 1
  fi
fi
echo "setup: installing ${missing[*]}"
"${as_root[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"

#!/usr/bin/env bash
# Installs the Debian 12 packages rockface needs to build and test, only
# those missing. Idempotent; run as root (or with sudo available).
set -euo pipefail

packages=(
  # toolchain
  g++ cmake ninja-build pkg-config
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
  # the block's motion after failure: Boost.Odeint (header-only, in libboost-dev)
  libboost-dev
  # the field report's PDF (cairo's PDF surface)
  libcairo2-dev
  # the office server (issue 24): libpq's C API, OpenSSL's SHA-256
  libpq-dev libssl-dev
  # 3D images from elsewhere and exports the office opens (issue 43): OBJ
  # (tinyobjloader), meshing of imported clouds and the hull of a block's
  # corners (CGAL, header-only), DXF (dxflib). PCD is read by a reader of
  # our own (storage/exchange/pcd_reader.h says why not Open3D's).
  libtinyobjloader-dev libcgal-dev libdxflib-dev
  # the office in a browser (issue 46): the HTTP server (cpp-httplib,
  # header-only) and three.js, served to the browser from the system's copy
  libcpp-httplib-dev libjs-three
)
# What only the tests and benchmarks need; `tools/setup.sh --demo` (what
# tools/demo.sh runs) leaves them out: 65 MB less to download of ~525, and
# no PostgreSQL cluster set up (docs/accuracy-cost.md, "The demo on a fresh
# machine").
if [ "${1:-}" != "--demo" ]; then
  packages+=(
    # compiler cache: CI runs on the session's machine, which keeps
    # ~/.cache; the demo's one build from nothing would only pay its misses
    ccache
    # the UI's window test: a virtual X server
    xvfb xauth
    # tests and benchmarks
    libgtest-dev libgmock-dev libbenchmark-dev
    # CI's check that no name repeats in one library's anonymous namespaces
    # (tools/check-unity-names.sh: the demo's unity build)
    universal-ctags
    # the report tests read the PDF back (pdftotext, pdftoppm)
    poppler-utils
    # the office tests: a real PostgreSQL server (initdb, pg_ctl) and openssl
    # to make the TLS test's CA and certificate
    postgresql openssl
    # libgphoto2's virtual PTP camera for the DSLR tests (issue 42,
    # tools/virtual-camera.sh): apt-get source (dpkg-dev), the port
    # library's configure and build (make, gcc from g++, patch for our
    # one-line patch, libltdl-dev which its configure requires); the
    # gphoto2 CLI to try the camera by hand (docs/virtual-camera.md)
    dpkg-dev make patch libltdl-dev gphoto2
    # the exports read back by the office's own readers (issue 43): ezdxf
    # for the DXF, CloudCompare's command line (under xvfb) for OBJ / PLY
    python3-ezdxf cloudcompare
    # the office's pages tested in a real browser (issue 46): headless
    # Chromium driven over WebDriver
    chromium chromium-driver
  )
fi

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

#!/usr/bin/env bash
# Installs the Debian packages tissue needs, and only those that are missing.
# Runs as root on a fresh Debian 12 (bookworm) machine; a no-op when all are present.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git clang-format
  libopenmesh-dev          # mesh module (adapter in libtissue/src/mesh)
  libeigen3-dev            # small dense linear algebra (plane fits, solvers)
  libglm-dev               # renderer maths
  libegl-dev libegl-mesa0 libgl-dev libgl1-mesa-dri   # EGL surfaceless context on Mesa llvmpipe
  libosmesa6-dev           # OSMesa fallback context
  libglfw3-dev             # windowed context (viewer)
  libimgui-dev             # the viewer's control panel (Dear ImGui 1.86; libimgui.a holds its GLFW and OpenGL 3 back ends)
  libvtk9-dev vtk9 python3-vtk9   # inspection module; vtk9 and python3-vtk9 carry files VTK's CMake config names
  nlohmann-json3-dev       # JSON output and data files
  python3-glad             # generates the GL 3.3 core loader at build time (no download)
  libstb-dev               # PNG read/write
  libcli11-dev             # command-line parsing
  libgtest-dev libgmock-dev libbenchmark-dev   # tests and benchmarks
  xvfb xauth               # X server for VTK views and GLFW windows without a display
  libssl-dev               # SHA-256 of simulated positions (recorded sessions, replay): libtissue/src/scene
  libembree-dev            # ray-mesh queries of the path-traced truth (libtissue/src/truth/embree_mesh.cpp; optional)
  libx11-dev               # Xlib: the chart adapter opens the display it hands VTK (libtissue/src/inspect)
  clang libclang-rt-dev    # libFuzzer and the sanitizer runtimes: the fuzz targets (tests/fuzz)
  ccache                   # compiler cache: the second and third test trees reuse the first's objects
)

# --paraview: ParaView too, for the pvpython test of the .pvd series (tests/inspect/pvd_pvpython_test.sh,
# configure with -DTISSUE_TEST_PARAVIEW=ON). Not by default: about 1 GB with its dependencies. Debian 12's
# python3-paraview conflicts with libvtk9-dev and python3-vtk9 (installing it removes this build's VTK), so
# its files are unpacked into /opt/tissue-paraview instead, where the test points pvbatch's PYTHONPATH.
paraview_python() {
  [ "${1:-}" = "--paraview" ] && [ ! -d /opt/tissue-paraview/usr/lib/python3/dist-packages/paraview ] || return 0
  (cd /tmp && apt-get download python3-paraview && dpkg -x python3-paraview_*.deb /opt/tissue-paraview && rm -f python3-paraview_*.deb)
}
if [ "${1:-}" = "--paraview" ]; then packages+=(paraview); fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  paraview_python "${1:-}"
  exit 0
fi

if [ "$(id -u)" -ne 0 ]; then
  echo "install-deps: missing packages: ${missing[*]}; run this script as root (or sudo) to install them" >&2
  exit 1
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
paraview_python "${1:-}"

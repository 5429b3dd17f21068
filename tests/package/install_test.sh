#!/usr/bin/env bash
# The installed tissue as a host sees it (ctest label "package"):
#   install_test.sh <cmake> <build dir> <source dir> <work dir> <mesh>
# installs the build into <work>/prefix, checks the installed headers (no third-party header, no
# internal GL header, every tissue include resolvable inside the prefix) and libraries (no path
# of the source or build tree), checks the exported targets (check_exports/), then configures,
# builds and runs the out-of-tree consumer (consumer_cpp/) and the example hosts (examples/) against the prefix.
set -u
cmake="$1" build="$(realpath "$2")" source="$(realpath "$3")" work="$4" mesh="$(realpath "$5")"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
status=0
fail() { echo "FAIL $*"; status=1; }
rm -rf "$work" && mkdir -p "$work"
prefix="$work/prefix"

"$cmake" --install "$build" --prefix "$prefix" >"$work/install.log" 2>&1 || { cat "$work/install.log"; echo "FAIL cmake --install"; exit 1; }
for f in tissueConfig.cmake tissueConfigVersion.cmake tissueTargets.cmake tissueGlfwTargets.cmake; do
  [ -s "$prefix/lib/cmake/tissue/$f" ] || fail "no lib/cmake/tissue/$f"
done
for h in tissue/tissue.h tissue/scene/organ_loop.h tissue/scene/session.h tissue/render/renderer.h \
         tissue/context/headless_context.h tissue/mesh/load_mesh.h tissue/sim/simulator.h \
         tissue/scenario/scenario.h tissue/materials/method_materials.h tissue/volume/tet_mesh.h; do
  [ -s "$prefix/include/$h" ] || fail "header $h not installed"
done

# Headers: no third-party tree, no glad-including GL header, only standard <...> includes.
third=$(find "$prefix/include" -type d \( -iname 'openmesh' -o -iname 'eigen*' -o -iname 'vtk*' -o -iname 'glad' -o -name 'GL' \
          -o -name 'EGL' -o -name 'KHR' -o -iname 'glm' -o -iname 'nlohmann' -o -iname 'glfw*' \) -print)
[ -z "$third" ] || fail "third-party headers installed: $third"
for h in gl/gl_api.h gl/objects.h gl/program.h; do
  [ ! -e "$prefix/include/tissue/$h" ] || fail "internal header tissue/$h (includes glad) installed"
done
nonstd=$(grep -rhoE '^ *# *include *<[^>]+>' "$prefix/include" | grep -E '[./]' | sort -u)
[ -z "$nonstd" ] || fail "installed headers include non-standard headers: $nonstd"
while read -r inc; do
  [ -e "$prefix/include/$inc" ] || fail "an installed header includes \"$inc\", which is not installed"
done < <(grep -rhoE '^ *# *include *"[^"]+"' "$prefix/include" | sed -E 's/.*"(.*)"/\1/' | sort -u)
nh=$(find "$prefix/include" -name '*.h' | wc -l)

# Libraries: static modules; nothing in them names the source or build tree (nothing is read
# from there at run time: the shaders are embedded).
nl=$(find "$prefix/lib" -name 'libtissue_*.a' | wc -l)
[ "$nl" -ge 15 ] || fail "only $nl libtissue_*.a installed"
for tree in "$source" "$build"; do
  named=$(grep -lF "$tree" "$prefix"/lib/*.a 2>/dev/null)
  [ -z "$named" ] || fail "installed libraries name $tree: $named"
done
echo "installed: $nh headers, $nl static libraries"

launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi

# Exports: version rule, targets, include directories, no GLFW in the headless link interface.
"$cmake" -S "$here/check_exports" -B "$work/check-exports" -DCMAKE_PREFIX_PATH="$prefix" \
  -DTISSUE_PREFIX="$prefix" >"$work/check-exports.log" 2>&1 || { cat "$work/check-exports.log"; fail "export checks"; }
grep "tissue package:" "$work/check-exports.log"

# A missing dependency fails find_package(tissue) with one message that names it and the fix.
if "$cmake" -S "$here/check_exports" -B "$work/check-missing" -DCMAKE_PREFIX_PATH="$prefix" -DTISSUE_PREFIX="$prefix" \
  -DCMAKE_DISABLE_FIND_PACKAGE_OpenMesh=TRUE >"$work/check-missing.log" 2>&1; then
  fail "find_package(tissue) succeeded without OpenMesh"
fi
{ grep -q "link OpenMesh (tissue::mesh reads" "$work/check-missing.log" && grep -q "libopenmesh-dev" "$work/check-missing.log"; } ||
  { cat "$work/check-missing.log"; fail "no clear message for a missing OpenMesh"; }

# The consumer: configure out of tree, build, run.
"$cmake" -S "$here/consumer_cpp" -B "$work/consumer-build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" \
  "${launcher[@]}" >"$work/consumer-configure.log" 2>&1 || { cat "$work/consumer-configure.log"; echo "FAIL consumer configure"; exit 1; }
"$cmake" --build "$work/consumer-build" >"$work/consumer-build.log" 2>&1 || { cat "$work/consumer-build.log"; echo "FAIL consumer build"; exit 1; }
(cd "$work" && "$work/consumer-build/tissue_consumer" "$mesh" "$work/frame.png") || fail "consumer run"
[ -s "$work/frame.png" ] || fail "the consumer wrote no frame"

# The example hosts (examples/), out of tree against the prefix, as a simulator engineer builds
# them. The C host (compiled as C, tissue::tissue_c): the data liver with its scenario, poked; a
# non-zero force, a non-blank PNG, a missing mesh refused by name. The GLFW host (tissue::tissue,
# its own window and raw GL, under Xvfb): its instrument hides the tissue behind it and the
# tissue hides its floor, pixel by pixel.
data="$source/data"
clauncher=()
if command -v ccache >/dev/null; then clauncher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache); fi
"$cmake" -S "$source/examples/c_host" -B "$work/c-host-build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" \
  "${clauncher[@]}" >"$work/c-host-configure.log" 2>&1 || { cat "$work/c-host-configure.log"; fail "c_host configure"; }
"$cmake" --build "$work/c-host-build" >"$work/c-host-build.log" 2>&1 || { cat "$work/c-host-build.log"; fail "c_host build"; }
"$work/c-host-build/c_host" "$data" "$work/c_host.png" || fail "c_host run"
"$cmake" -S "$source/examples/host_glfw" -B "$work/host-glfw-build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" \
  "${launcher[@]}" >"$work/host-glfw-configure.log" 2>&1 || { cat "$work/host-glfw-configure.log"; fail "host_glfw configure"; }
"$cmake" --build "$work/host-glfw-build" >"$work/host-glfw-build.log" 2>&1 || { cat "$work/host-glfw-build.log"; fail "host_glfw build"; }
if command -v xvfb-run >/dev/null; then
  xvfb-run -a "$work/host-glfw-build/host_glfw" "$data" --frames 150 --check "$work/host_glfw.png" || fail "host_glfw run"
else
  fail "xvfb-run is missing (Debian package xvfb): the GLFW host needs an X server"
fi
[ "$status" -eq 0 ] && echo "package: install, exports, the consumer and both example hosts pass"
exit "$status"

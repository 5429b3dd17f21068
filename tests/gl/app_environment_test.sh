#!/usr/bin/env bash
# The apps, not the library, read TISSUE_GL_CONTEXT, TISSUE_EGL_PLATFORM and TISSUE_SHADER_DIR
# and pass them in: each setting reaches tissue-sim's context and renderer, and a bad one is one
# line naming the variable and the choices.
set -u
sim="$1"; dir="$2"; rm -rf "$dir"; mkdir -p "$dir"
status=0
fail() { echo "FAIL $*"; status=1; }

TISSUE_GL_CONTEXT=osmesa "$sim" --json info >"$dir/osmesa.json" 2>/dev/null || fail "info with osmesa: exit $?"
grep -q '"gl_context": "osmesa"' "$dir/osmesa.json" || fail "TISSUE_GL_CONTEXT=osmesa did not reach the context"
TISSUE_GL_CONTEXT=egl TISSUE_EGL_PLATFORM=surfaceless "$sim" --json info >"$dir/egl.json" 2>/dev/null \
  || fail "info with egl surfaceless: exit $?"
grep -q '"gl_platform": "surfaceless"' "$dir/egl.json" || fail "TISSUE_EGL_PLATFORM did not reach EGL"
TISSUE_GL_CONTEXT=vulkan "$sim" info >"$dir/out.txt" 2>"$dir/err.txt"; rc=$?
{ [ "$rc" -ne 0 ] && [ "$(wc -l <"$dir/err.txt")" -eq 1 ] && grep -q "TISSUE_GL_CONTEXT" "$dir/err.txt"; } \
  || fail "a bad backend: exit $rc, $(cat "$dir/err.txt")"
# A shader override folder whose lit shader does not compile: the render must fail naming it.
mkdir -p "$dir/shaders/lit"
printf '#version 330 core\nthis does not compile\n' >"$dir/shaders/lit/lit.frag"
TISSUE_SHADER_DIR="$dir/shaders" "$sim" render --out "$dir/x.png" --width 64 --height 48 >"$dir/out.txt" 2>"$dir/err.txt"; rc=$?
{ [ "$rc" -ne 0 ] && grep -q "lit" "$dir/err.txt"; } || fail "TISSUE_SHADER_DIR was not used: exit $rc"
"$sim" render --out "$dir/y.png" --width 64 --height 48 >/dev/null 2>&1 || fail "render without overrides failed"
[ "$status" -eq 0 ] && echo "ok"
exit $status

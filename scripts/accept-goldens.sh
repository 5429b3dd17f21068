#!/usr/bin/env bash
# Re-accepts golden images: copies the actual images the GL tests wrote
# (<build>/test-output/golden/<name>.png) over tests/golden/<name>.png.
# Usage: scripts/accept-goldens.sh [BUILD_DIR] [NAME...]   (BUILD_DIR defaults to build/)
# Run the gl tests first (ctest --test-dir BUILD_DIR -L gl), look at the actual and
# .diff.png images, then accept. Only names given (or all when none) are copied.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build}"
shift || true
actual_dir="$build/test-output/golden"
golden_dir="$root/tests/golden"
if [[ ! -d "$actual_dir" ]]; then
  echo "accept-goldens: no $actual_dir; run 'ctest --test-dir $build -L gl' first" >&2
  exit 1
fi
mkdir -p "$golden_dir"
count=0
for file in "$actual_dir"/*.png; do
  [[ -e "$file" ]] || continue
  name="$(basename "$file" .png)"
  [[ "$name" == *.diff ]] && continue
  if [[ $# -gt 0 ]]; then
    wanted=0
    for n in "$@"; do [[ "$n" == "$name" ]] && wanted=1; done
    [[ $wanted -eq 1 ]] || continue
  fi
  cp "$file" "$golden_dir/$name.png"
  echo "accepted $name"
  count=$((count + 1))
done
echo "accept-goldens: $count image(s) copied into $golden_dir"

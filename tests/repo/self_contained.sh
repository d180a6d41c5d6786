#!/usr/bin/env bash
# The repository stands on its own: no tracked file points outside it (into a sibling folder of
# the development machine or at an absolute path of one), and the documents the README, the code
# and --help cite are in docs/.
set -euo pipefail
src=$1
cd "$src"
if ! git rev-parse --is-inside-work-tree >/dev/null 2>&1; then echo "self_contained: not a git checkout, skipped"; exit 0; fi
pattern='\.\./'"shared|shared/""docs|/""work/|/""home/[a-z]|/""root/"
hits=$(git ls-files -z | xargs -0 grep -lE "$pattern" 2>/dev/null || true)
if [ -n "$hits" ]; then echo "self_contained: these tracked files name a path outside the repository:"; echo "$hits"; exit 1; fi
for d in docs/method.md docs/profiles.md docs/glossary.md LICENSE NOTICE; do
  [ -f "$d" ] || { echo "self_contained: $d is missing"; exit 1; }
done
# Every docs/*.md the README cites exists.
for d in $(grep -o 'docs/[A-Za-z0-9_.-]*\.md' README.md | sort -u); do
  [ -f "$d" ] || { echo "self_contained: README cites $d, which does not exist"; exit 1; }
done
echo "self_contained: OK"

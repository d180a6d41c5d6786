#!/usr/bin/env bash
# One run per directory: a rerun replaces the previous set of files as a whole (a rerun with
# --format csv or without --pressure-grid leaves no results.json or pressure.csv of the earlier
# run behind); DIR/run.json lists exactly the files of the run; a directory holding foreign
# files is refused and left untouched.
set -uo pipefail
bin=$1; src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0
fail() { echo "FAIL: $*"; fails=1; }
listed() { python3 -c 'import json,sys; print(" ".join(json.load(open(sys.argv[1]))["files"]))' "$1/run.json"; }
present() { (cd "$1" && ls | sort | tr '\n' ' ' | sed 's/ $//'); }
d="$tmp/out"
"$bin" run "$src/cases/manchester-plastic.json" -o "$d" --pressure-grid 5 -q
[ "$(present "$d")" = "cases.csv ellipses.csv geometry.csv pressure.csv profiles.csv results.json run.json" ] || fail "first run: $(present "$d")"
[ "$(listed "$d")" = "$(present "$d")" ] || fail "run.json lists $(listed "$d"), the directory holds $(present "$d")"
"$bin" run "$src/cases/manchester.json" -o "$d" --format csv -q
[ "$(present "$d")" = "cases.csv ellipses.csv geometry.csv profiles.csv run.json" ] || fail "rerun --format csv: $(present "$d")"
[ "$(listed "$d")" = "$(present "$d")" ] || fail "rerun: run.json lists $(listed "$d")"
grep -q '"command": "run"' "$d/run.json" || fail "run.json has no command"
# A default plot of the previous run goes with it.
echo png > "$d/pressure_case_3.png"
"$bin" run "$src/cases/manchester.json" -o "$d" --format csv -q || fail "rerun over a plot"
[ ! -e "$d/pressure_case_3.png" ] || fail "the previous run's plot stayed beside the new tables"
# A directory with a file no run wrote is refused (exit 2) and left as it was.
echo "notes" > "$d/my_notes.txt"
before=$(present "$d")
"$bin" run "$src/cases/manchester.json" -o "$d" -q 2>"$tmp/err"; rc=$?
[ $rc = 2 ] || fail "foreign file: exit $rc, wanted 2"
grep -q "my_notes.txt: the output directory holds a file that no mhcontact run wrote" "$tmp/err" || fail "foreign file: $(cat "$tmp/err")"
[ "$(present "$d")" = "$before" ] || fail "a refused run changed the directory"
# geometry and merge replace their directory the same way.
rm "$d/my_notes.txt"
"$bin" geometry "$src/cases/manchester.json" -o "$d" -q
[ "$(present "$d")" = "caf.csv geometry.json profiles.csv run.json" ] || fail "geometry into a run directory: $(present "$d")"
ls -d "$tmp"/.out.* >/dev/null 2>&1 && fail "a temporary directory was left behind"
exit $fails

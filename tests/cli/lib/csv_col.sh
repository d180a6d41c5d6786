# Columns of a CSV table by their header names, for the tests in tests/cli (source this file).
# A test that picks columns by position goes on passing, comparing the wrong columns, when a
# column is added; by name it fails when a name goes missing. Quoted fields ("a,b", "" inside)
# are read as one field. Portable awk (mawk, gawk, busybox).
#
#   csv_col FILE NAME [NAME...]   the named columns of every data row, joined by commas
#                                 (quoted fields printed without their quotes); exit 2 naming
#                                 the column and the file when a name is not in the header
#   csv_idx FILE NAME             the 1-based position of NAME in the header (exit 2 if absent),
#                                 for awk programs: awk -F, -v c="$(csv_idx f.csv status)" '$c == "ok"'

_csv_awk='
function split_csv(line, f,    n, i, c, q, cur) {
  n = 0; cur = ""; q = 0
  for (i = 1; i <= length(line); i++) {
    c = substr(line, i, 1)
    if (q) {
      if (c == "\"") { if (substr(line, i + 1, 1) == "\"") { cur = cur "\""; i++ } else q = 0 }
      else cur = cur c
    } else if (c == "\"") q = 1
    else if (c == ",") { f[++n] = cur; cur = "" }
    else if (c != "\r") cur = cur c
  }
  f[++n] = cur
  return n
}
NR == 1 {
  n = split_csv($0, h)
  for (i = 1; i <= n; i++) pos[h[i]] = i
  m = split(names, want, " ")
  for (k = 1; k <= m; k++)
    if (!(want[k] in pos)) { printf "csv_col: no column \"%s\" in %s (header: %s)\n", want[k], file, $0 > "/dev/stderr"; bad = 1; exit 2 }
  if (index_only) { print pos[want[1]]; exit 0 }
  next
}
{
  split_csv($0, f)
  s = ""
  for (k = 1; k <= m; k++) s = s (k > 1 ? "," : "") f[pos[want[k]]]
  print s
}
END { if (bad) exit 2 }'

csv_col() {
  local file=$1; shift
  [ -r "$file" ] || { echo "csv_col: cannot read $file" >&2; return 2; }
  awk -v names="$*" -v file="$file" -v index_only=0 "$_csv_awk" "$file"
}

csv_idx() {
  [ -r "$1" ] || { echo "csv_idx: cannot read $1" >&2; return 2; }
  awk -v names="$2" -v file="$1" -v index_only=1 "$_csv_awk" "$1"
}

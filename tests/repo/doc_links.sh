#!/usr/bin/env bash
# The documents hold together: every relative link of README.md and docs/*.md points to a file
# that exists and, when it names a heading (#anchor), to a heading of that file (anchors as
# GitHub makes them: lower case, punctuation dropped, spaces to hyphens, -1, -2 … for repeats);
# and docs/README.md lists every page of docs/.
set -uo pipefail
src=$1
check_tree() {  # prints the broken links of the tree $1, returns 1 if any
  python3 - "$1" <<'PY'
import os, re, sys, unicodedata
root = sys.argv[1]

def strip_code(text):
    text = re.sub(r"^```.*?^```", "", text, flags=re.S | re.M)    # fenced blocks
    return re.sub(r"`[^`\n]*`", "", text)                          # code spans

def anchors(path):
    seen, out = {}, set()
    text = re.sub(r"^```.*?^```", "", open(path, encoding="utf-8").read(), flags=re.S | re.M)
    for m in re.finditer(r"^#{1,6}\s+(.*?)\s*#*\s*$", text, re.M):
        h = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", m.group(1))  # a link keeps its text
        h = h.lower()
        h = "".join(c for c in h if c in " -_" or unicodedata.category(c)[0] in "LN")
        h = h.replace(" ", "-")
        n = seen.get(h, 0)
        seen[h] = n + 1
        out.add(h if n == 0 else f"{h}-{n}")
    return out

pages = ["README.md"] + ["docs/" + f for f in sorted(os.listdir(os.path.join(root, "docs"))) if f.endswith(".md")]
bad = 0
for page in pages:
    path = os.path.join(root, page)
    text = strip_code(open(path, encoding="utf-8").read())
    for m in re.finditer(r"\[[^\]]*\]\(([^)\s]+)\)", text):
        target = m.group(1)
        if re.match(r"[a-z][a-z0-9+.-]*:", target):      # http:, https:, mailto:
            continue
        file, _, anchor = target.partition("#")
        dest = os.path.normpath(os.path.join(os.path.dirname(path), file)) if file else path
        if not os.path.exists(dest):
            print(f"doc_links: {page}: link to {target}: {file} does not exist"); bad = 1
        elif anchor and dest.endswith(".md") and anchor not in anchors(dest):
            print(f"doc_links: {page}: link to {target}: no heading #{anchor} in {os.path.relpath(dest, root)}"); bad = 1
index = open(os.path.join(root, "docs", "README.md"), encoding="utf-8").read()
for page in pages:
    name = os.path.basename(page)
    if page.startswith("docs/") and name != "README.md" and f"]({name})" not in index:
        print(f"doc_links: docs/README.md does not list {page}"); bad = 1
sys.exit(bad)
PY
}
check_tree "$src" || exit 1
# The check must be able to fail: a missing file, a missing heading and an unlisted page are caught.
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/docs"
printf '# T\n\n[a](docs/a.md#no-such-heading) [b](docs/missing.md) [c](docs/a.md#heading-two)\n' > "$tmp/README.md"
printf '# A\n\n## Heading two\n' > "$tmp/docs/a.md"
printf '# Index\n\n[README](../README.md)\n' > "$tmp/docs/README.md"
out=$(check_tree "$tmp") && { echo "doc_links: the self-test was not caught"; exit 1; }
[ "$(echo "$out" | wc -l)" = 3 ] || { echo "doc_links: self-test expected 3 findings, got: $out"; exit 1; }
echo "doc_links: OK"

#!/bin/sh
# guide_walkthrough.sh TISSUEFIT MESH — the first steps of "Bringing a new
# organ" in docs/scene-format.md, as written: step 1's scene (the first
# yaml block after "**1. Look at the file.**"; only its mesh path, which
# depends on where a user keeps the scene, is replaced by MESH) and step
# 2's command (the first sh block after "**2. Look at the organ**") run in
# an empty folder; the command must exit 0 and leave a complete PNG.
set -eu
tool=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
mesh=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
doc=docs/scene-format.md
w=$(mktemp -d)
trap 'rm -rf "$w"' EXIT
# block MARKER LANG: the first ```LANG block after the line holding MARKER
block() {
    awk -v m="$1" -v l='```'"$2" 'index($0, m) { on = 1 } on && $0 == l { inb = 1; next }
        inb && $0 == "```" { exit } inb { print }' "$doc"
}
block '**1. Look at the file.**' yaml |
    sed "s|^\( *file: \)[^ #]*|\1$mesh|" >"$w/liver.yaml"
cmd=$(block '**2. Look at the organ**' sh)
[ -s "$w/liver.yaml" ] && [ -n "$cmd" ] || { echo "$doc: step 1's scene or step 2's command not found"; exit 1; }
grep -q "file: $mesh" "$w/liver.yaml" || { echo "$doc: step 1's scene names no mesh file"; exit 1; }
png=$(echo "$cmd" | sed -n 's/.*--png-rest \([^ ]*\).*/\1/p')
cmd=$(echo "$cmd" | sed "s|^tissuefit |$tool |")
( cd "$w" && sh -c "$cmd" ) >"$w/out" 2>&1 || { cat "$w/out"; echo "step 2 as written failed: $cmd"; exit 1; }
[ -n "$png" ] && [ -s "$w/$png" ] && tail -c 12 "$w/$png" | grep -q IEND ||
    { echo "step 2 wrote no complete $png"; exit 1; }
echo "ok: the new-organ walkthrough's steps 1 and 2 as written (docs/scene-format.md): scene read, $png drawn, nothing solved"

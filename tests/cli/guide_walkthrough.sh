#!/bin/sh
# guide_walkthrough.sh TISSUEFIT MESH — "Bringing a new organ" in
# docs/scene-format.md, steps 1 to 7 as written, in an empty folder:
#  1. the scene (the first yaml block after "**1. Look at the file.**"; only
#     its mesh path, which depends on where a user keeps the scene, is
#     replaced by MESH);
#  2. the rest picture's command: exit 0 and a complete PNG;
#  3-5. the yaml blocks of "**3. Hold it.**", "**4. Touch it.**" and
#     "**5. Choose the outputs**" put into the scene, each top-level key
#     replacing the one of the same name (as a user edits the file);
#  6. the solve's command: the CSV, the VTK file and a complete PNG;
#  7. the fit's command: a header that compiles, with its output map, and
#     the report; its self-measured discretisation says the file's skin
#     was not refined.
# Step 5b's spacing (6 mm) is not applied: it only refines the solve.
set -eu
tool=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
mesh=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
doc=docs/scene-format.md
inc=$(pwd)/target/include
w=$(mktemp -d)
trap 'rm -rf "$w"' EXIT
# block MARKER LANG: the first ```LANG block after the line holding MARKER
block() {
    awk -v m="$1" -v l='```'"$2" 'index($0, m) { on = 1 } on && $0 == l { inb = 1; next }
        inb && $0 == "```" { exit } inb { print }' "$doc"
}
# edit MARKER: the step's yaml block into the scene, replacing its keys
edit() {
    block "$1" yaml >"$w/step.yaml"
    [ -s "$w/step.yaml" ] || { echo "$doc: no yaml block after '$1'"; exit 1; }
    keys=$(sed -n 's/^\([a-z_]*\):.*/\1/p' "$w/step.yaml" | tr '\n' ' ')
    awk -v keys=" $keys" '/^[a-z_]+:/ { k = $0; sub(/:.*/, "", k); drop = index(keys, " " k " ") > 0 }
        !drop { print }' "$w/liver.yaml" >"$w/scene.tmp"
    cat "$w/scene.tmp" "$w/step.yaml" >"$w/liver.yaml"
}
# run STEP MARKER: the step's sh command, as written, in the folder
run() {
    cmd=$(block "$2" sh)
    [ -n "$cmd" ] || { echo "$doc: step $1's command not found"; exit 1; }
    ( cd "$w" && sh -c "$(echo "$cmd" | sed "s|^tissuefit |$tool |")" ) >"$w/out" 2>&1 ||
        { cat "$w/out"; echo "step $1 as written failed: $cmd"; exit 1; }
}
png_ok() {
    [ -s "$w/$1" ] && tail -c 12 "$w/$1" | grep -q IEND || { echo "step $2 wrote no complete $1"; exit 1; }
}
block '**1. Look at the file.**' yaml |
    sed "s|^\( *file: \)[^ #]*|\1$mesh|" >"$w/liver.yaml"
[ -s "$w/liver.yaml" ] || { echo "$doc: step 1's scene not found"; exit 1; }
grep -q "file: $mesh" "$w/liver.yaml" || { echo "$doc: step 1's scene names no mesh file"; exit 1; }
run 2 '**2. Look at the organ**'
png_ok rest.png 2
edit '**3. Hold it.**'
edit '**4. Touch it.**'
edit '**5. Choose the outputs**'
run 6 '**6. Solve once and look**'
png_ok deformed.png 6
[ "$(head -1 "$w/u.csv")" = "node,x,y,z,ux,uy,uz" ] && grep -q UnstructuredGrid "$w/u.vtu" ||
    { echo "step 6 wrote no displacement CSV or VTK file"; exit 1; }
run 7 '**7. Fit and emit the header**'
printf '#include "liver.h"\nconst void *v = tfit_liver_vertex;\n' |
    ${CC:-gcc} -std=c11 -Wall -Werror -I"$inc" -I"$w" -fsyntax-only -x c - ||
    { echo "step 7's liver.h does not compile with its output map"; exit 1; }
[ -s "$w/reports/liver.md" ] || { echo "step 7 wrote no report"; exit 1; }
# the skin is the file's (no refine_skin): the header says what the
# self-measured discretisation leaves out
grep -q "(discretisation: self-measured: .*; the file's skin on every cloud: the surface's part of the error is not in this figure" "$w/liver.h" ||
    { echo "step 7's liver.h does not say that its discretisation leaves the file's skin out"; exit 1; }
n=$(grep -c '^ *- sphere\|^ *- name\|^outputs' "$w/liver.yaml")
echo "ok: the new-organ walkthrough's steps 1 to 7 as written (docs/scene-format.md): rest.png, the solve's CSV, VTK and PNG, liver.h with its output map and report ($n entries edited in)"

#!/bin/sh
# check_versions.sh VERSION [TFIT_H TFIT_Q31_H VERSIONS_MD] — the versions
# docs/versions.md states against those the sources state: the table row of
# VERSION's major release must carry tfit.h's TFIT_API_VERSION and
# tfit_q31.h's TFIT_Q31_API_VERSION.  A new API version without a new major release (or
# a major release without its row) fails here.  Without file arguments it
# first shows itself a tfit.h whose API version moved on within the same
# major release, and must refuse it.
set -eu
version=$1
h=${2:-target/include/tfit.h}
q=${3:-target/include/tfit_q31.h}
md=${4:-docs/versions.md}
major=${version%%.*}

if [ $# = 1 ]; then
    tmp=$(mktemp -d)
    trap 'rm -rf "$tmp"' EXIT
    api=$(awk '$1 == "#define" && $2 == "TFIT_API_VERSION" { print $3 }' "$h")
    sed "s/^#define TFIT_API_VERSION $api\$/#define TFIT_API_VERSION $((api + 1))/" "$h" >"$tmp/tfit.h"
    if "$0" "$version" "$tmp/tfit.h" "$q" "$md" >"$tmp/out" 2>&1; then
        echo "FAIL: check_versions.sh accepted TFIT_API_VERSION $((api + 1)) in release $version"; exit 1
    fi
    grep -q "needs a new major release" "$tmp/out" || { cat "$tmp/out"; exit 1; }
fi

api=$(awk '$1 == "#define" && $2 == "TFIT_API_VERSION" { print $3 }' "$h")
q31=$(awk '$1 == "#define" && $2 == "TFIT_Q31_API_VERSION" { print $3 }' "$q")
[ -n "$api" ] && [ -n "$q31" ] || { echo "FAIL: no TFIT_API_VERSION / TFIT_Q31_API_VERSION in $h, $q"; exit 1; }
# Rows "| N.x | API | Q31 API |" of the table under "## Release history".
rows=$(awk '/^## /{ t = ($0 ~ /^## Release history/) } t && /^\| *[0-9]+\.x *\|/' "$md" |
       tr -d ' ' | awk -F'|' '{ sub(/\.x$/, "", $2); print $2, $3, $4 }')
row=$(printf '%s\n' "$rows" | awk -v m="$major" '$1 == m')
[ -n "$row" ] || { echo "FAIL: $md has no row for the major release $major.x (VERSION $version)"; exit 1; }
set -- $row
if [ "$2" != "$api" ] || [ "$3" != "$q31" ]; then
    echo "FAIL: $md: release $major.x carries TFIT_API_VERSION $2 and TFIT_Q31_API_VERSION $3;" \
         "the sources say $api and $q31: a new API version needs a new major release (docs/versions.md)"
    exit 1
fi
echo "versions: release $version carries TFIT_API_VERSION $api and TFIT_Q31_API_VERSION $q31, as $md states: ok"

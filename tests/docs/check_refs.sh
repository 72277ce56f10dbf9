#!/bin/sh
# check_refs.sh [ROOT] — README.md and docs/**/*.md state facts and cite the
# bibliography (docs/bibliography.md); they never point at documents outside
# the repository.  Rejected, outside code (fenced blocks and `inline`): a
# reference to an issue or pull request by number ("issue 31", "#31"), to
# the project's planning guide ("GUIDE"), or to a paper by a seed number
# ("seed 000") instead of its citation key.  Prints FILE:LINE: TEXT for
# each and exits 1 if there is any.
#
# check_refs.sh --selftest — shows the checker a tree with one of each,
# requires it to reject every one and to accept the clean lines, then checks
# the repository it sits in.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)

check() {
    root=$1
    files=$( { [ -f "$root/README.md" ] && echo "$root/README.md";
               [ -d "$root/docs" ] && find "$root/docs" -name '*.md'; } | sort)
    perl -CSD -e '
use strict; use warnings;
my $bad = 0;
for my $f (@ARGV) {
    open my $h, "<:encoding(UTF-8)", $f or die "$f: $!\n";
    my ($fence, $n) = ("", 0);
    while (my $l = <$h>) {
        ++$n;
        if ($l =~ /^\s*(```|~~~)/) { $fence = $fence ? "" : $1; next; }
        next if $fence;
        (my $t = $l) =~ s/`[^`]*`//g;
        $t =~ s/\]\([^)]*\)/]/g;                 # link targets (#anchors)
        if ($t =~ /\b(?:issues?|PR|pull requests?)\s*#?\d+/i
            || $t =~ /(?:^|[\s(,;])#\d+\b/
            || $t =~ /\bGUIDE\b/
            || $t =~ /\bseeds?\s*0\d\d\b/i) {
            chomp $l;
            print "$f:$n: $l\n";
            ++$bad;
        }
    }
}
exit($bad ? 1 : 0);
' $files
}

if [ "${1:-}" = "--selftest" ]; then
    tmp=$(mktemp -d) || exit 1
    trap 'rm -rf "$tmp"' EXIT
    mkdir -p "$tmp/docs"
    printf '%s\n' 'Fixed in issue 31.' 'See #34 for why.' 'As GUIDE §5 defines it.' \
        'After seed 001 eq 9.' >"$tmp/docs/bad.md"
    printf '%s\n' 'After [EFG-Kelvin] eq 9, see [the table](#31-the-table).' \
        'The `SSAT #14` instruction.' '```' 'issue 31 inside a code block' '```' >"$tmp/README.md"
    out=$(check "$tmp")
    for want in 'bad.md:1:' 'bad.md:2:' 'bad.md:3:' 'bad.md:4:'; do
        case $out in
            *"$want"*) ;;
            *) echo "check_refs selftest: $want was not rejected" >&2; exit 1 ;;
        esac
    done
    case $out in
        *README.md*) echo "check_refs selftest: a clean line was rejected: $out" >&2; exit 1 ;;
    esac
    shift
fi

echo "== docs: no reference to an issue number or a document outside the repository =="
if check "${1:-$here}"; then
    echo "ok: README.md and docs/ cite only the bibliography and their own files"
else
    exit 1
fi

#!/bin/sh
# check_links.sh [ROOT] — every relative Markdown link in ROOT/README.md and
# ROOT/docs/**/*.md, [text](path) or [text](path#anchor) or [text](#anchor),
# images included, must name a file or folder that exists, and its anchor a
# heading of that Markdown file, slugged as GitHub does (lower case; every
# character that is not a letter, a digit, '_', '-' or a space dropped;
# spaces to '-'; a repeated slug gets -1, -2, ...).  Links inside code
# (fenced blocks, `inline`) and to other schemes (https:, mailto:) are not
# checked.  Prints one line per broken link and exits 1 if there is any.
#
# check_links.sh --selftest — shows the checker a tree with a missing file,
# a missing anchor and a missing image, requires it to reject each, then
# checks the repository it sits in.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)

check() {
    root=$1
    files=$( { [ -f "$root/README.md" ] && echo "$root/README.md";
               [ -d "$root/docs" ] && find "$root/docs" -name '*.md'; } | sort)
    # perl is part of every Debian system (perl-base) and knows Unicode's
    # letter and digit classes, which GitHub's slugs keep.
    perl -CSD -Mutf8 -e '
use strict; use warnings;
my ($root, @files) = @ARGV;
my %slugs;          # file -> { slug -> 1 }
sub headings {
    my ($f) = @_;
    return $slugs{$f} if $slugs{$f};
    my %seen; my %set; my $fence = "";
    open my $h, "<:encoding(UTF-8)", $f or return $slugs{$f} = {};
    while (my $l = <$h>) {
        if ($l =~ /^\s*(```|~~~)/) { $fence = $fence ? "" : $1; next; }
        next if $fence;
        next unless $l =~ /^#{1,6}\s+(.*?)\s*#*\s*$/;
        my $t = lc $1;
        $t =~ s/\[([^\]]*)\]\([^)]*\)/$1/g;      # a link in a heading: its text
        $t =~ s/[^\p{Word}\- ]//g;
        $t =~ s/ /-/g;
        my $s = $t;
        $s .= "-" . $seen{$t} if $seen{$t};
        $seen{$t}++;
        $set{$s} = 1;
    }
    return $slugs{$f} = \%set;
}
my ($links, $bad) = (0, 0);
for my $f (@files) {
    open my $h, "<:encoding(UTF-8)", $f or die "$f: $!\n";
    my $fence = ""; my $n = 0;
    (my $dir = $f) =~ s{/[^/]*$}{};
    while (my $l = <$h>) {
        ++$n;
        if ($l =~ /^\s*(```|~~~)/) { $fence = $fence ? "" : $1; next; }
        next if $fence;
        $l =~ s/`[^`]*`//g;                       # inline code
        while ($l =~ /!?\[[^\]]*\]\(([^)\s]+)(?:\s+"[^"]*")?\)/g) {
            my $t = $1;
            next if $t =~ /^[a-z][a-z0-9+.-]*:/i;  # https:, mailto:, ...
            ++$links;
            my ($path, $anchor) = $t =~ /^([^#]*)(?:#(.*))?$/;
            my $target = $path eq "" ? $f : "$dir/$path";
            (my $shown = $f) =~ s{^\Q$root\E/}{};
            if (!-e $target) {
                print "$shown:$n: $t: no such file\n"; ++$bad; next;
            }
            next unless defined $anchor && $anchor ne "";
            if ($target !~ /\.md$/ || -d $target) {
                print "$shown:$n: $t: an anchor into a file that is not Markdown\n"; ++$bad; next;
            }
            if (!headings($target)->{$anchor}) {
                print "$shown:$n: $t: no heading with that anchor\n"; ++$bad;
            }
        }
    }
}
print "links: $links checked, $bad broken\n";
exit($bad ? 1 : 0);
' "$root" $files
}

if [ "${1:-}" = --selftest ]; then
    echo "== docs: every relative link names an existing file and heading =="
    t=$(mktemp -d) || exit 1
    trap 'rm -rf "$t"' EXIT
    mkdir -p "$t/docs"
    printf '# Top\n\n## 1. Two words (a, b) × c\n\n## 1. Two words (a, b) × c\n' >"$t/docs/a.md"
    printf '[ok](a.md#1-two-words-a-b--c) [ok](a.md#1-two-words-a-b--c-1) [ok](#b)\n\n# B\n' >"$t/docs/b.md"
    printf '[x](docs/a.md#top)\n' >"$t/README.md"
    if ! check "$t" >"$t/out" 2>&1; then
        echo "the checker refused a tree whose links all resolve:"; cat "$t/out"; exit 1
    fi
    for broken in '[x](docs/none.md)' '[x](docs/a.md#nowhere)' '![x](docs/none.png)' '[x](#top)'; do
        printf '%s\n' "$broken" >"$t/README.md"
        if check "$t" >"$t/out" 2>&1; then
            echo "the checker accepted a broken link: $broken"; exit 1
        fi
    done
    check "$here" || exit 1
    echo "ok: every relative link in README.md and docs/ resolves (and 4 broken links were refused)"
    exit 0
fi
check "${1:-$here}"

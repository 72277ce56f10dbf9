#!/bin/sh
# check_errors.sh DIR — one error convention in host/ (DIR): a fallible
# function takes the run's context first (tf_ctx *ctx, base/context.h) and
# reports with tf_fail, so no file may declare the older pair of a message
# buffer and its size:
#   - a `char *...err...` parameter followed by a `size_t` one (over line
#     breaks too), whatever the size is called;
#   - the name `errlen` anywhere (a parameter, a member, a local).
# Prints one line per violation and the verdict; exits 1 on any violation.
set -u
dir=$1
files=$(find "$dir" -name '*.[ch]' | LC_ALL=C sort)
# perl is part of every Debian system (perl-base); -0777 reads a file whole,
# so a pair split over two lines is seen.
out=$(perl -0777 -ne '
    my $f = $ARGV; $f =~ s{^\Q'"$dir"'\E/}{};
    while (/char\s*\*\s*(?:const\s+)?\w*err\w*\s*,\s*size_t\s+\w+/g) {
        my $line = 1 + (substr($_, 0, $-[0]) =~ tr/\n//);
        (my $m = $&) =~ s/\s+/ /g;
        print "host/$f:$line: a message buffer and its size ($m): take tf_ctx *ctx first and report with tf_fail (base/context.h)\n";
    }
    while (/\berrlen\b/g) {
        my $line = 1 + (substr($_, 0, $-[0]) =~ tr/\n//);
        print "host/$f:$line: errlen: the buffer-and-size error convention is gone; take tf_ctx *ctx first (base/context.h)\n";
    }' $files)
n=$(echo "$files" | wc -l)
if [ -n "$out" ]; then
    echo "$out" | sort -u
    echo "FAIL: host/ error convention ($n files)"
    exit 1
fi
echo "ok: host/ error convention: $n files, no (char *err, size_t errlen) pair; fallible functions take tf_ctx *ctx first"

#!/usr/bin/env python3
"""findings.py TREE CPPCHECK MISRA TIDY — one line per finding, "ID FILE:LINE:COLUMN",
FILE relative to TREE, from the outputs analyse.sh collected:

  CPPCHECK  cppcheck's own findings, --template='cppcheck {id} {file}:{line}:{column}'
  MISRA     misra.py --cli: one JSON object per finding (other lines are its summary)
  TIDY      clang-tidy: "FILE:LINE:COL: warning: TEXT [check,alias]" (notes skipped)

Anything in them that is not a finding or a known summary line is an error:
a tool that printed something unexpected has not been understood."""
import json
import os
import re
import sys


def rel(tree, path):
    path = os.path.normpath(os.path.join(tree, path))
    r = os.path.relpath(path, tree)
    if r.startswith(".."):
        sys.exit("findings.py: a finding outside the tree: " + path)
    return r


def main():
    tree, cppcheck, misra, tidy = sys.argv[1:5]
    out = []
    with open(cppcheck) as f:
        for line in f:
            m = re.match(r"cppcheck (\S+) (\S+):(\d+):(\d+)$", line.rstrip("\n"))
            if m:
                out.append("%s %s:%s:%s" % (m[1], rel(tree, m[2]), m[3], m[4]))
            # the lines after a finding repeat the source and point at it
    with open(misra) as f:
        for line in f:
            if line.startswith("{"):
                j = json.loads(line)
                if j.get("addon") != "misra":
                    sys.exit("findings.py: not a misra finding: " + line)
                out.append("misra-%s %s:%d:%d" % (j["errorId"], rel(tree, j["file"]),
                                                  j["linenr"], j["column"]))
            elif line.strip() and not re.match(r"\s*(MISRA rules violat|misra-c2012-\S+ \(|"
                                                r"style: \d+|c2012-)", line):
                sys.exit("findings.py: unexpected misra.py output: " + line)
    with open(tidy) as f:
        for line in f:
            m = re.match(r"(\S+?):(\d+):(\d+): (warning|error): .* \[([^\]]+)\]$", line.rstrip("\n"))
            if m:
                check = m[5].split(",")[0]
                out.append("%s %s:%s:%s" % (check, rel(tree, m[1]), m[2], m[3]))
            elif re.match(r"\S+:\d+:\d+: (warning|error):", line):
                sys.exit("findings.py: clang-tidy finding without a check name: " + line)
    for o in out:
        print(o)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""judge.py — libtfit's static-analysis findings against their record, docs/misra.md.

  judge.py check FINDINGS RECORD CLANG_TIDY
      FINDINGS is analyse.sh's findings.txt ("ID FILE:LINE:COLUMN").  Fails
      (exit 1), naming each line, when a finding's rule is not recorded for
      its file, when a file has more findings of a rule than recorded (a new
      violation of a rule the file already deviates from), or fewer (the
      record is stale: lower the count or drop the row).  Also fails when the
      clang-tidy checks target/.clang-tidy turns off are not exactly those
      the record's "Checks not run" table lists.
  judge.py suppressions RECORD
      The record as a cppcheck suppressions list (ID:FILE), for
      `cppcheck --addon=misra --suppressions-list=...`; tests/misra/suppressions.txt
      is this output, and check-misra keeps it so.
  judge.py rows FINDINGS
      The findings as the record's tables: a starting point when code changes.

The record: a deviation is a heading "### Rule R.N ..." (misra-c2012-R.N),
"### cppcheck ID ..." or "### clang-tidy CHECK ...", followed by rows
"| `FILE` | COUNT |".  The checks not run are the rows "| `CHECK` | why |"
of the table under the heading "## clang-tidy: checks not run"."""
import collections
import re
import sys


def read_findings(path):
    found = collections.defaultdict(list)  # (id, file) -> ["file:line:col"]
    with open(path) as f:
        for line in f:
            fid, loc = line.split()
            found[(fid, loc.split(":")[0])].append(loc)
    return found


def read_record(path):
    record, not_run = {}, set()
    fid, section = None, ""
    with open(path) as f:
        for n, line in enumerate(f, 1):
            if line.startswith("## "):
                section, fid = line[3:].strip(), None
                continue
            m = re.match(r"### (Rule (\d+\.\d+)|cppcheck ([^\s:]+)|clang-tidy ([^\s:]+))", line)
            if m:
                fid = "misra-c2012-" + m[2] if m[2] else (m[3] or m[4])
                continue
            if line.startswith("### "):
                fid = None
                continue
            m = re.match(r"\| `([^`]+)` \| (\d+) \|\s*$", line)
            if m and fid:
                key = (fid, m[1])
                if key in record:
                    sys.exit("%s:%d: %s %s recorded twice" % (path, n, fid, m[1]))
                record[key] = int(m[2])
                continue
            m = re.match(r"\| `([a-z0-9.-]+)` \|", line)
            if m and section.startswith("clang-tidy: checks not run"):
                not_run.add(m[1])
    return record, not_run


def tidy_disabled(path):
    """The checks a .clang-tidy turns off ("-name" in Checks:, plain or a YAML block)."""
    value, inside = "", False
    with open(path) as f:
        for line in f:
            if line.startswith("Checks:"):
                value, inside = line[len("Checks:"):], True
            elif inside and line[:1] in " \t" and line.strip():
                value += line
            else:
                inside = False
    checks = [c.strip() for c in value.strip().strip(">-").strip("'\"").split(",") if c.strip()]
    if not checks:
        sys.exit("%s: no Checks: entry" % path)
    return {c[1:] for c in checks if c.startswith("-") and c != "-*"}


def is_cppcheck(fid):
    return fid.startswith("misra-") or "-" not in fid


def check(findings_path, record_path, tidy_path):
    found = read_findings(findings_path)
    record, not_run = read_record(record_path)
    bad = 0
    for key in sorted(found, key=lambda k: (k[1], k[0])):
        fid, fname = key
        locs = sorted(found[key], key=lambda s: [int(x) if x.isdigit() else x for x in s.split(":")])
        allowed = record.get(key, 0)
        if allowed == 0:
            for loc in locs:
                print("not in the record: %s %s" % (fid, loc))
            bad += 1
        elif len(locs) > allowed:
            print("more than the record allows: %s %s: %d findings, recorded %d:" % (fid, fname, len(locs), allowed))
            for loc in locs:
                print("    %s" % loc)
            bad += 1
        elif len(locs) < allowed:
            print("stale record: %s %s: %d findings, recorded %d (update docs/misra.md)" % (fid, fname, len(locs), allowed))
            bad += 1
    for key in sorted(set(record) - set(found)):
        print("stale record: %s %s: no finding, recorded %d (drop the row from docs/misra.md)" % (key[0], key[1], record[key]))
        bad += 1
    disabled = tidy_disabled(tidy_path)
    for c in sorted(disabled - not_run):
        print("%s turns off %s, which the record's 'checks not run' table does not list" % (tidy_path, c))
        bad += 1
    for c in sorted(not_run - disabled):
        print("the record lists %s as not run, but %s runs it" % (c, tidy_path))
        bad += 1
    if bad:
        print("%d difference(s) between the findings and %s" % (bad, record_path))
        return 1
    ids = {k[0] for k in record}
    print("findings: %d, all recorded (%d rules and checks in %d files); clang-tidy checks not run: %d, all listed"
          % (sum(len(v) for v in found.values()), len(ids), len({k[1] for k in record}), len(disabled)))
    return 0


def suppressions(record_path):
    record, _ = read_record(record_path)
    print("# cppcheck suppressions for libtfit: the deviations of %s, generated by" % record_path)
    print("# tests/misra/judge.py suppressions %s (check-misra keeps this file so)." % record_path)
    for fid, fname in sorted(record, key=lambda k: (k[0], k[1])):
        if is_cppcheck(fid):
            print("%s:%s" % (fid, fname))
    return 0


def rows(findings_path):
    found = read_findings(findings_path)
    by_id = collections.defaultdict(list)
    for (fid, fname), locs in found.items():
        by_id[fid].append((fname, len(locs)))
    def order(fid):
        m = re.match(r"misra-c2012-(\d+)\.(\d+)$", fid)
        return (0, int(m[1]), int(m[2]), "") if m else (1, 0, 0, fid)
    for fid in sorted(by_id, key=order):
        m = re.match(r"misra-c2012-(\d+\.\d+)$", fid)
        title = ("Rule " + m[1]) if m else (("cppcheck " if is_cppcheck(fid) else "clang-tidy ") + fid)
        print("### %s\n\n| file | findings |\n|---|---|" % title)
        for fname, n in sorted(by_id[fid]):
            print("| `%s` | %d |" % (fname, n))
        print()
    return 0


def main():
    a = sys.argv[1:]
    if len(a) == 4 and a[0] == "check":
        return check(a[1], a[2], a[3])
    if len(a) == 2 and a[0] == "suppressions":
        return suppressions(a[1])
    if len(a) == 2 and a[0] == "rows":
        return rows(a[1])
    sys.exit(__doc__)


if __name__ == "__main__":
    sys.exit(main())

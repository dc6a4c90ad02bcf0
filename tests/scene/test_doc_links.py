#!/usr/bin/python3
"""Pages: every link between the project's pages lands.

1. Every relative link in README.md, docs/*.md and results/**/*.md names a
   file or folder that exists, and a link with #anchor names a heading of
   the page it points to (GitHub's anchors: the heading in lower case,
   punctuation but hyphens dropped, spaces as hyphens).
2. Every folder under results/ is a row of results/README.md's table.

Reads files only (no LIGGGHTS run); the launcher argument is not used.
"""
import os
import re

import scene_util as su

LINK = re.compile(r"\]\(([^)\s]+)\)")
HEADING = re.compile(r"^#+\s+(.*?)\s*$")


def anchors(path):
    out = set()
    with open(path, encoding="utf-8") as f:
        for line in f:
            m = HEADING.match(line)
            if m:
                slug = re.sub(r"[^\w\- ]", "", m.group(1).lower()).replace(" ", "-")
                out.add(slug)
    return out


def pages(root):
    found = [os.path.join(root, "README.md")]
    for sub in ("docs", "results"):
        for d, _, names in os.walk(os.path.join(root, sub)):
            found += [os.path.join(d, n) for n in names if n.endswith(".md")]
    return sorted(found)


def main():
    args = su.parse_args(__doc__)
    chk = su.Checker()
    root = args.source
    bad, n_links = [], 0
    files = pages(root)
    for page in files:
        text = open(page, encoding="utf-8").read()
        for m in LINK.finditer(text):
            url = m.group(1)
            if re.match(r"[a-z]+:", url):
                continue
            n_links += 1
            path, _, anchor = url.partition("#")
            target = os.path.normpath(os.path.join(os.path.dirname(page), path)) if path else page
            where = "%s: %s" % (os.path.relpath(page, root), url)
            if not os.path.exists(target):
                bad.append(where + " (no such file)")
            elif anchor and target.endswith(".md") and anchor not in anchors(target):
                bad.append(where + " (no such heading)")
    chk.check("%d relative links in %d pages, each to a file that exists and a heading "
              "that exists" % (n_links, len(files)), n_links > 50 and not bad, "\n".join(bad))

    index = open(os.path.join(root, "results", "README.md"), encoding="utf-8").read()
    folders = sorted(d for d in os.listdir(os.path.join(root, "results"))
                     if os.path.isdir(os.path.join(root, "results", d)))
    missing = [d for d in folders if "(%s/README.md)" % d not in index]
    chk.check("every results folder (%d) is a row of results/README.md" % len(folders),
              folders and not missing, "missing: %s" % missing)
    chk.finish()


if __name__ == "__main__":
    main()

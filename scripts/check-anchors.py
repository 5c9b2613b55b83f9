#!/usr/bin/env python3
"""Check that every in-page link `[..](#anchor)` and every link to
`FILE.md#anchor` in the Markdown docs names a heading that exists, with
GitHub's rule for heading anchors (lowercase; letters, digits, `_`, `-`
and spaces kept; spaces become `-`; a repeated heading gets `-1`, `-2`).

Usage: scripts/check-anchors.py [FILES...]  (default: README.md,
ARCHITECTURE.md, CHANGELOG.md and docs/*.md). Exit 1 on a broken anchor,
printing each with the headings' anchors nearest to it.
"""
import difflib
import pathlib
import re
import sys
import unicodedata


def slug(heading):
    text = re.sub(r"`([^`]*)`", r"\1", heading.strip()).lower()
    kept = []
    for ch in text:
        cat = unicodedata.category(ch)
        if ch in " -_" or cat[0] in "LMN":
            kept.append(ch)
    return "".join(kept).replace(" ", "-")


def anchors(path):
    seen, out = {}, set()
    fence = False
    for line in path.read_text(encoding="utf-8").splitlines():
        if line.lstrip().startswith("```"):
            fence = not fence
            continue
        m = None if fence else re.match(r"#{1,6}\s+(.*?)\s*#*\s*$", line)
        if m:
            s = slug(m.group(1))
            n = seen.get(s, 0)
            seen[s] = n + 1
            out.add(s if n == 0 else f"{s}-{n}")
    return out


def main(argv):
    root = pathlib.Path(__file__).resolve().parent.parent
    files = [pathlib.Path(a) for a in argv] or (
        [root / "README.md", root / "ARCHITECTURE.md", root / "CHANGELOG.md"]
        + sorted((root / "docs").glob("*.md"))
    )
    bad = 0
    for f in files:
        text = f.read_text(encoding="utf-8")
        for target, anchor in re.findall(r"\]\(([^)#\s]*)#([^)\s]+)\)", text):
            if target.startswith("http"):
                continue
            doc = (f.parent / target).resolve() if target else f
            if doc.suffix != ".md" or not doc.exists():
                continue
            have = anchors(doc)
            if anchor not in have:
                bad += 1
                near = difflib.get_close_matches(anchor, sorted(have), n=1)
                hint = f" (nearest heading: #{near[0]})" if near else ""
                print(f"{f.relative_to(root)}: #{anchor} is no heading of {doc.name}{hint}")
    if bad:
        print(f"{bad} broken anchor(s)")
        return 1
    print(f"anchors: {len(files)} files checked, all links to headings resolve")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

#!/usr/bin/python3
"""Checks that every relative link of the repository's markdown resolves.

    scripts/check_links.py [ROOT]

For each `*.md` under ROOT (default: the repository; build folders and .git skipped), every inline
link and image `[text](target)` outside code blocks and code spans whose target is not a URL must
name a file or folder that exists, relative to the markdown file; a `#fragment` into a markdown file
must match one of its headings as GitHub spells anchors (lower case, punctuation dropped, spaces to
hyphens).
Prints one line per broken link, `FILE:LINE: target (why)`, and exits 1 if there is any.
"""
import argparse
import pathlib
import re
import sys

LINK = re.compile(r"!?\[(?:[^\]\\]|\\.)*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
CODE_SPAN = re.compile(r"(`+).+?\1")
SKIPPED_DIRS = {".git", "build", "results"}


def markdown_files(root):
    for path in sorted(root.rglob("*.md")):
        parts = path.relative_to(root).parts
        if not any(part in SKIPPED_DIRS or part.startswith("build") for part in parts[:-1]):
            yield path


def prose_lines(text):
    """(line number, line) outside fenced code blocks, with code spans blanked."""
    fence = None
    for number, line in enumerate(text.splitlines(), 1):
        stripped = line.lstrip()
        marker = re.match(r"(`{3,}|~{3,})", stripped)
        if marker:
            if fence is None:
                fence = marker.group(1)[0] * 3
            elif stripped.startswith(fence):
                fence = None
            continue
        if fence is None:
            yield number, CODE_SPAN.sub(lambda m: " " * len(m.group(0)), line)


def github_anchor(heading):
    """The fragment GitHub gives a heading: lower case, markup and punctuation dropped, spaces to hyphens."""
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", heading.strip().lower())
    text = re.sub(r"[^\w\- ]", "", text.replace("`", ""))
    return text.replace(" ", "-")


def anchors(path, cache={}):
    """The anchors of a markdown file's headings (outside code blocks), repeats numbered as GitHub does."""
    if path not in cache:
        seen = {}
        fence = None
        for line in path.read_text(encoding="utf-8").splitlines():
            stripped = line.lstrip()
            marker = re.match(r"(`{3,}|~{3,})", stripped)
            if marker:
                if fence is None:
                    fence = marker.group(1)[0] * 3
                elif stripped.startswith(fence):
                    fence = None
                continue
            heading = re.match(r"#{1,6}\s+(.*?)\s*#*\s*$", line) if fence is None else None
            if heading:
                anchor = github_anchor(heading.group(1))
                seen[anchor] = seen.get(anchor, -1) + 1
                seen[f"{anchor}-{seen[anchor]}" if seen[anchor] else anchor] = seen.get(anchor)
        cache[path] = set(seen)
    return cache[path]


def broken_links(root):
    for path in markdown_files(root):
        for number, line in prose_lines(path.read_text(encoding="utf-8")):
            for match in LINK.finditer(line):
                target = match.group(1)
                if re.match(r"[a-z][a-z0-9+.-]*:", target, re.I):  # http:, https:, mailto:
                    continue
                file_part, _, fragment = target.partition("#")
                resolved = (path.parent / file_part).resolve() if file_part else path
                where = f"{path.relative_to(root)}:{number}: {target}"
                if not resolved.exists():
                    yield f"{where} (no such file)"
                    continue
                if fragment and resolved.suffix == ".md" and fragment not in anchors(resolved):
                    yield f"{where} (no heading with that anchor in {resolved.relative_to(root)})"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("root", nargs="?", default=pathlib.Path(__file__).resolve().parent.parent)
    args = parser.parse_args()
    root = pathlib.Path(args.root).resolve()
    problems = list(broken_links(root))
    for problem in problems:
        print(problem)
    files = sum(1 for _ in markdown_files(root))
    print(f"check_links: {files} markdown files, {len(problems)} broken links")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

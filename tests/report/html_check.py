#!/usr/bin/env python3
"""Checks that a report page is self-contained: no scripts, no external style sheets or fonts,
no address with a scheme or an absolute path, and every relative image it references exists
inside the report's directory. Prints the images it found.

Usage: html_check.py REPORT.html MIN_IMAGES MIN_SVGS
"""
import html.parser
import os
import re
import sys


class Collector(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.refs, self.problems, self.images, self.svgs = [], [], [], 0

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag == "script":
            self.problems.append("a <script> element")
        if tag == "link":
            self.problems.append(f"a <link> element ({attrs.get('href')})")
        if tag == "svg":
            self.svgs += 1
        if tag == "img":
            self.images.append(attrs.get("src", ""))
        for name in ("src", "href", "srcset", "xlink:href", "data"):
            if attrs.get(name):
                self.refs.append(attrs[name])


def main():
    path, min_images, min_svgs = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    text = open(path, encoding="utf-8").read()
    c = Collector()
    c.feed(text)
    base = os.path.dirname(os.path.abspath(path))
    for ref in c.refs:
        if ref.startswith("data:") or ref.startswith("#"):
            continue
        if re.match(r"^[a-zA-Z][a-zA-Z0-9+.-]*:", ref) or ref.startswith("/"):
            c.problems.append(f"an external reference: {ref}")
            continue
        target = os.path.normpath(os.path.join(base, ref))
        if not target.startswith(base + os.sep):
            c.problems.append(f"a reference outside the report's directory: {ref}")
        elif not os.path.isfile(target):
            c.problems.append(f"a missing file: {ref}")
    for pattern in (r"@import", r"url\(\s*['\"]?(https?:|//)", r"@font-face"):
        if re.search(pattern, text):
            c.problems.append(f"style sheet pulls in something ({pattern})")
    if len(c.images) < min_images:
        c.problems.append(f"{len(c.images)} images, expected at least {min_images}")
    if c.svgs < min_svgs:
        c.problems.append(f"{c.svgs} inline SVG charts, expected at least {min_svgs}")
    for problem in c.problems:
        print(f"{path}: {problem}")
    for image in c.images:
        print(f"image {image}")
    return 1 if c.problems else 0


if __name__ == "__main__":
    sys.exit(main())

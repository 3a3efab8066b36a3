#!/usr/bin/env python3
"""readmeIsTrue: the README's commands, paths and tutorials table are true.

    tests/docs/readmeIsTrue.py [projectDir]

Checks, and prints one line per failure (exit 1 if any):
  - every repository path that README.md and docs/user-guide.md name, in
    inline code or in a code block (a word that starts with a top-level
    entry of the repository: etc/, src/, applications/, tutorials/, tests/,
    docs/, .ci/, Allwmake, Allclean), exists;
  - every relative link of README.md and of docs/*.md points at a file
    that exists, and its #anchor, if any, at a heading of that file (the
    anchors GitHub makes: lower case, punctuation dropped, spaces to '-');
  - the table under README's "## Tutorials" lists exactly the tutorials
    there are: the folders tutorials/*/* that hold an Allrun.
Run by ctest as docs.readmeIsTrue; runs standalone from any directory.
"""
import glob
import os
import re
import sys

TOP = ("etc/", "src/", "applications/", "tutorials/", "tests/", "docs/",
       ".ci/", "Allwmake", "Allclean")


def slug(heading):
    """The anchor GitHub gives a Markdown heading"""
    text = re.sub(r"`|\*\*|\*", "", heading.strip().lower())
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def read_markdown(path):
    """(prose lines, code lines, anchors): lines outside and inside fenced
    code blocks, with their numbers, and the anchors of the headings"""
    prose, code, anchors, seen = [], [], set(), {}
    fence = False
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            if line.lstrip().startswith("```"):
                fence = not fence
                continue
            if fence:
                code.append((n, line))
                continue
            prose.append((n, line))
            m = re.match(r"(#{1,6}) +(.*?)\s*#*\s*$", line)
            if m:
                a = slug(m.group(2))
                k = seen.get(a, 0)
                seen[a] = k + 1
                anchors.add(a if k == 0 else "%s-%d" % (a, k))
    return prose, code, anchors


def paragraphs(prose):
    """(first line number, text) of each paragraph: an inline code span may
    run over a line break"""
    out, start, text = [], None, []
    for n, line in prose + [(None, "")]:
        if line.strip():
            start = start or n
            text.append(line)
        elif text:
            out.append((start, " ".join(text)))
            start, text = None, []
    return out


def expand(word):
    """a/{b,c}/d -> a/b/d, a/c/d"""
    m = re.match(r"(.*?)\{([^{}]*)\}(.*)", word)
    if not m:
        return [word]
    return [w for part in m.group(2).split(",")
            for w in expand(m.group(1) + part + m.group(3))]


def repo_words(text):
    """The words of text that name a repository path"""
    out = []
    for w in re.split(r"[\s`'\"()\[\]=|]+", text):
        w = w.rstrip(".,;:")
        if w.startswith("./"):
            w = w[2:]
        if not w.startswith(TOP) or re.search(r"[<>*$…]", w):
            continue
        out.extend(expand(w))
    return out


def main(argv):
    root = os.path.abspath(argv[1] if len(argv) > 1 else
                           os.path.join(os.path.dirname(__file__), "..", ".."))
    failures = []

    def fail(where, what):
        failures.append("%s: %s" % (where, what))

    readme = os.path.join(root, "README.md")
    guide = os.path.join(root, "docs", "user-guide.md")
    pages = [readme] + sorted(glob.glob(os.path.join(root, "docs", "*.md")))
    parsed = {p: read_markdown(p) for p in pages if os.path.isfile(p)}
    for p in (readme, guide):
        if p not in parsed:
            fail(os.path.relpath(p, root), "missing")

    # Paths named in README and the user guide
    for page in (readme, guide):
        if page not in parsed:
            continue
        prose, code, _ = parsed[page]
        name = os.path.relpath(page, root)
        for n, para in paragraphs(prose):
            for span in re.findall(r"`([^`]+)`", para):
                for w in repo_words(span):
                    if not os.path.exists(os.path.join(root, w)):
                        fail("%s:%d" % (name, n), "no such path: " + w)
        for n, line in code:
            for w in repo_words(line):
                if not os.path.exists(os.path.join(root, w)):
                    fail("%s:%d" % (name, n), "no such path: " + w)

    # Links and their anchors, in README and every docs page
    for page, (prose, _, anchors) in parsed.items():
        name = os.path.relpath(page, root)
        for n, line in prose:
            for target in re.findall(r"\]\(([^)\s]+)\)", line):
                if re.match(r"[a-z]+:", target):
                    continue
                path, _, anchor = target.partition("#")
                file = os.path.normpath(os.path.join(os.path.dirname(page), path)) \
                    if path else page
                if not os.path.exists(file):
                    fail("%s:%d" % (name, n), "link to a missing file: " + target)
                    continue
                if anchor:
                    if file not in parsed and file.endswith(".md"):
                        parsed[file] = read_markdown(file)
                    if file not in parsed or anchor not in parsed[file][2]:
                        fail("%s:%d" % (name, n), "no heading for the anchor: " + target)

    # The tutorials table lists exactly the tutorials
    tutorials = sorted(os.path.relpath(os.path.dirname(a), root)
                       for a in glob.glob(os.path.join(root, "tutorials", "*", "*", "Allrun")))
    listed, inSection, inTable = [], False, False
    for n, line in parsed.get(readme, ([], [], set()))[0]:
        if line.startswith("## "):
            inSection = line.strip() == "## Tutorials"
            continue
        if inSection and line.startswith("|"):
            inTable = True
            cell = line.split("|")[1]
            listed += re.findall(r"`(tutorials/[^`]+)`", cell)
        elif inTable:
            break
    if not listed:
        fail("README.md", "no tutorials table under '## Tutorials'")
    for t in sorted(set(tutorials) - set(listed)):
        fail("README.md", "tutorial not in the table: " + t)
    for t in sorted(set(listed) - set(tutorials)):
        fail("README.md", "table row that is no tutorial: " + t)
    for t in sorted(t for t in set(listed) if listed.count(t) > 1):
        fail("README.md", "tutorial listed twice: " + t)

    for f in failures:
        print("readmeIsTrue: " + f)
    if failures:
        return 1
    print("readmeIsTrue: README paths, links and the %d tutorials are true"
          % len(tutorials))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

#!/usr/bin/python3
"""Checks docs/architecture.md against the source tree, both ways.

    check_architecture.py [REPOSITORY_ROOT]

1. Every repository path the document names in inline code (a backticked
   token containing '/' or ending in a source or documentation extension;
   `{h,cpp}`-style braces expanded) must exist under the root. A path ending
   in '/' must be a folder.
2. Every file under the code folders (engine/, kernels/, vis/ except
   vis/python/, app/, bench/) must be named by the document, as itself or
   through a brace pair.

Prints each missing and each unmentioned path; exits 1 if there is any,
0 otherwise. The root defaults to two levels above this script. Fenced code
blocks (diagrams) are not read. Only the standard library is used.
"""

import os
import re
import sys

DOCUMENT = os.path.join("docs", "architecture.md")

#: Tokens without a '/' count as paths only with one of these endings;
#: file names of data (model.obj, strokes.json) are not repository paths.
EXTENSIONS = (".h", ".hpp", ".c", ".cpp", ".cxx", ".cl", ".in", ".py", ".sh", ".md", ".txt", ".module",
              ".cmake")

#: Folders whose every file the document must name, and what is left out.
CODE_FOLDERS = ("engine", "kernels", "vis", "app", "bench")
EXCLUDED = ("vis/python",)

#: A token that can be a path: no spaces, no wildcards or placeholders.
PATH_TOKEN = re.compile(r"^[A-Za-z0-9_.+\-/{},]+$")
BRACES = re.compile(r"\{([^{}]*)\}")


def inline_code(text):
    """The inline code spans of a Markdown text, outside fenced blocks."""
    spans = []
    fenced = False
    paragraph = []
    for line in text.splitlines():
        if line.lstrip().startswith("```"):
            fenced = not fenced
            continue
        if not fenced:
            paragraph.append(line)
    # Spans may not run over a line end in this document's style, but a
    # span split by wrapping is joined back: read the text as one string.
    joined = "\n".join(paragraph)
    for match in re.finditer(r"(`+)(.+?)\1", joined, re.S):
        spans.append(match.group(2).strip())
    return spans


def expand(token):
    """`a.{h,cpp}` -> [a.h, a.cpp]; several braces multiply."""
    match = BRACES.search(token)
    if not match:
        return [token]
    out = []
    for alternative in match.group(1).split(","):
        out.extend(expand(token[:match.start()] + alternative + token[match.end():]))
    return out


def looks_like_path(token):
    if not PATH_TOKEN.match(token) or token.startswith("-") or "://" in token:
        return False
    return "/" in token or any(p.endswith(EXTENSIONS) for p in expand(token))


def mentioned_paths(text):
    paths = []
    for span in inline_code(text):
        if looks_like_path(span):
            for path in expand(span):
                if path not in paths:
                    paths.append(path)
    return paths


def code_files(root):
    """Files under the code folders, relative to root, with '/' separators."""
    files = []
    for folder in CODE_FOLDERS:
        for directory, subdirs, names in os.walk(os.path.join(root, folder)):
            relative_dir = os.path.relpath(directory, root).replace(os.sep, "/")
            subdirs[:] = sorted(d for d in subdirs if not d.startswith(".") and d != "__pycache__" and
                                not any((relative_dir + "/" + d).startswith(e) for e in EXCLUDED))
            for name in sorted(names):
                if name.startswith(".") or name.endswith(("~", ".swp", ".orig", ".rej", ".pyc")):
                    continue
                files.append(relative_dir + "/" + name)
    return files


def main(argv):
    root = argv[1] if len(argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
    root = os.path.abspath(root)
    document = os.path.join(root, DOCUMENT)
    try:
        with open(document, encoding="utf-8") as f:
            text = f.read()
    except OSError as e:
        print("cannot read %s: %s" % (document, e.strerror))
        return 1

    paths = mentioned_paths(text)
    missing = []
    for path in paths:
        full = os.path.join(root, path.rstrip("/"))
        if not (os.path.isdir(full) if path.endswith("/") else os.path.exists(full)):
            missing.append(path)
    for path in missing:
        print("%s names a path that does not exist: %s" % (DOCUMENT, path))

    named = {p.rstrip("/") for p in paths}
    unmentioned = [f for f in code_files(root) if f not in named]
    for path in unmentioned:
        print("%s does not mention: %s" % (DOCUMENT, path))

    if missing or unmentioned:
        return 1
    print("%s: %d paths exist; every file of %s is mentioned" %
          (DOCUMENT, len(paths), ", ".join(f + "/" for f in CODE_FOLDERS)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Check the repository's documents: links, anchors and runnable command blocks.

    python3 tools/docs/check_docs.py [--build HOST_BUILD_DIR] [--root DIR] [FILE.md ...]
    python3 tools/docs/check_docs.py --self-test

Without FILE arguments it checks README.md, CHANGELOG.md, docs/*.md and every port/**/README.md
and tools/**/README.md. For each:

  * every relative link and image, inline ([text](target)) or by reference ([x]: target), names a
    file or folder that exists (http:, https: and mailto: links are not fetched);
  * an anchor (#part) into a Markdown file matches one of its headings by GitHub's rule (lower
    case; letters, digits, '_', '-' and spaces kept; spaces become '-'; a repeated heading gets
    -1, -2, ...);
  * a line carrying <!-- pending --> holds a link whose file another branch is adding: it may be
    missing; once it exists the marker is an error, so it cannot go stale.

A RUNNABLE block is a fenced ```sh block right after a line <!-- runnable -->: the reader pastes
it as it is, from the repository's root. Running it here is not possible (README's two set-up
blocks install packages and take 18 minutes), so "runnable" is checked as far as a unit test can:

  * every script that `sh`, `bash` or `python3` runs, every command named by a path and every
    argument that names a repository path (a word with a '/', not an option, not a variable)
    exists in the tree; a path under build/ is a build output: with --build it must exist in that
    build tree (build/X -> HOST_BUILD_DIR/X; the block builds into build/);
  * `cmake --preset P`, `cmake --build --preset P` and `ctest --preset P` name a configure, build
    and test preset of CMakePresets.json;
  * `cmake -S DIR` names a folder of the tree;
  * .ci/run's last line is one of README's runnable blocks, word for word (CI runs exactly what
    README tells a newcomer to run).

Exit status 1 and one line per problem when anything fails. --self-test writes a small tree with
one good and one broken document (a missing file, a missing anchor, a runnable block naming a
missing script and an unknown preset, a stale pending marker) and checks that exactly those
problems are found and the good document passes. CTest: docs_links, docs_links_self_test.
"""
import glob
import json
import os
import re
import shlex
import sys
import tempfile

LINK = re.compile(r"\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
REF_DEF = re.compile(r"^\s{0,3}\[[^\]]+\]:\s*<?(\S+?)>?(?:\s+\"[^\"]*\")?\s*$")
FENCE = re.compile(r"^\s*(```|~~~)")
PENDING = "<!-- pending -->"
RUNNABLE = "<!-- runnable -->"


def slug(heading):
    """GitHub's anchor for a heading's text."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # links keep their text
    text = re.sub(r"<[^>]+>", "", text).strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(path):
    seen, found, in_code = {}, set(), False
    for line in open(path, encoding="utf-8").read().split("\n"):
        if FENCE.match(line):
            in_code = not in_code
            continue
        m = re.match(r"^\s{0,3}(#{1,6})\s+(.*?)\s*#*\s*$", line)
        if in_code or not m:
            continue
        base = slug(m.group(2))
        n = seen.get(base, 0)
        seen[base] = n + 1
        found.add(base if n == 0 else f"{base}-{n}")
    return found


def prose_lines(text):
    """(number, line) of the lines outside fenced code, inline code removed."""
    in_code = False
    for n, line in enumerate(text.split("\n"), 1):
        if FENCE.match(line):
            in_code = not in_code
            continue
        if not in_code:
            yield n, re.sub(r"`+[^`]*`+", "", line)


def check_link(root, doc, target, anchor_cache):
    """'' when target resolves, else what is wrong."""
    if re.match(r"^[a-z][a-z0-9+.-]*:", target, re.I):
        return ""  # http:, https:, mailto:: not fetched
    path, _, frag = target.partition("#")
    full = os.path.normpath(os.path.join(os.path.dirname(doc), path)) if path else doc
    if not os.path.exists(full):
        return f"link to {path}: no such file"
    if not os.path.realpath(full).startswith(os.path.realpath(root) + os.sep) and path:
        return f"link to {path}: outside the repository"
    if frag and full.endswith(".md"):
        if full not in anchor_cache:
            anchor_cache[full] = anchors(full)
        if frag not in anchor_cache[full]:
            return f"link to {target}: {os.path.relpath(full, root)} has no heading with anchor #{frag}"
    return ""


def check_links(root, doc):
    problems, cache = [], {}
    text = open(doc, encoding="utf-8").read()
    rel = os.path.relpath(doc, root)
    for n, line in prose_lines(text):
        targets = LINK.findall(line)
        m = REF_DEF.match(line)
        if m:
            targets.append(m.group(1))
        bad = [(t, check_link(root, doc, t, cache)) for t in targets]
        bad = [(t, why) for t, why in bad if why]
        if PENDING in line:
            if not bad:
                problems.append(f"{rel}:{n}: every link on this line resolves now: remove the {PENDING} marker")
            continue
        problems += [f"{rel}:{n}: {why}" for _, why in bad]
    return problems


def runnable_blocks(text):
    """[(line number, [command lines])] of the ```sh blocks right after a runnable marker."""
    lines, blocks, i = text.split("\n"), [], 0
    while i < len(lines):
        if lines[i].strip() == RUNNABLE:
            j = i + 1
            if j >= len(lines) or not re.match(r"^```(sh|bash|shell)?\s*$", lines[j]):
                blocks.append((i + 1, None))
                i += 1
                continue
            k = j + 1
            while k < len(lines) and not lines[k].startswith("```"):
                k += 1
            blocks.append((j + 2, lines[j + 1:k]))
            i = k
        i += 1
    return blocks


def presets(root):
    try:
        data = json.load(open(os.path.join(root, "CMakePresets.json"), encoding="utf-8"))
    except OSError:
        return {}
    return {kind: {p["name"] for p in data.get(kind + "Presets", [])} for kind in ("configure", "build", "test")}


def check_command(root, build, words, known_presets):
    """What is wrong with one simple command (a list of words)."""
    bad = []
    if not words:
        return bad

    def path_ok(word):
        if word.startswith("build/"):
            if build is None:
                return ""
            out = os.path.join(build, word[len("build/"):])
            return "" if os.path.exists(out) else f"{word}: not in the build tree ({out})"
        return "" if os.path.exists(os.path.join(root, word)) else f"{word}: no such file in the tree"

    prog = words[0]
    if prog in ("sh", "bash", "python3") and len(words) > 1:
        why = path_ok(words[1])
        bad += [why] if why else []
        args = words[2:]
    else:
        if "/" in prog:
            why = path_ok(prog)
            bad += [why] if why else []
        args = words[1:]
    if prog in ("cmake", "ctest") and "--preset" in args:
        name = args[args.index("--preset") + 1] if args.index("--preset") + 1 < len(args) else ""
        kind = "test" if prog == "ctest" else "build" if "--build" in args else "configure"
        if name not in known_presets.get(kind, set()):
            bad.append(f"{prog} --preset {name}: no {kind} preset of that name in CMakePresets.json")
    if prog == "cmake" and "-S" in args:
        src = args[args.index("-S") + 1] if args.index("-S") + 1 < len(args) else ""
        if not os.path.isdir(os.path.join(root, src)):
            bad.append(f"cmake -S {src}: no such folder")
    for a in args:
        if "/" in a and not a.startswith(("-", "$")) and "=" not in a and not re.match(r"^[a-z]+://", a):
            why = path_ok(a)
            bad += [why] if why else []
    return bad


def split_commands(line):
    """The simple commands of a shell line: split at &&, ||, ;, |."""
    out = []
    for part in re.split(r"&&|\|\||;|\|", line):
        try:
            words = shlex.split(part, comments=True)
        except ValueError:
            words = part.split()
        if words:
            out.append(words)
    return out


def check_runnable(root, doc, build):
    problems = []
    rel = os.path.relpath(doc, root)
    known = presets(root)
    blocks = runnable_blocks(open(doc, encoding="utf-8").read())
    for n, block in blocks:
        if block is None:
            problems.append(f"{rel}:{n}: {RUNNABLE} is not followed by a ```sh block")
            continue
        joined = " ".join(l.rstrip("\\").strip() for l in block)
        for words in split_commands(joined):
            problems += [f"{rel}:{n}: runnable block: {why}" for why in check_command(root, build, words, known)]
    return problems, [" ".join(l.rstrip("\\").strip() for l in b) for _, b in blocks if b]


def check_ci(root, readme_blocks):
    ci = os.path.join(root, ".ci", "run")
    if not os.path.exists(ci):
        return []
    lines = [l.strip() for l in open(ci, encoding="utf-8").read().split("\n") if l.strip() and not l.startswith("#")]
    last = lines[-1] if lines else ""
    if last not in readme_blocks:
        return [f".ci/run: its command {last!r} is none of README's runnable blocks"]
    return []


def default_docs(root):
    docs = ["README.md", "CHANGELOG.md"] + sorted(glob.glob("docs/*.md", root_dir=root))
    for pattern in ("port/**/README.md", "tools/**/README.md"):
        docs += sorted(glob.glob(pattern, root_dir=root, recursive=True))
    return [d for d in docs if os.path.exists(os.path.join(root, d))]


def check(root, build, docs):
    problems = []
    for d in docs:
        path = os.path.join(root, d)
        problems += check_links(root, path)
        found, blocks = check_runnable(root, path, build)
        problems += found
        if d == "README.md":
            problems += check_ci(root, blocks)
    return problems


def self_test():
    """The checker finds each planted fault, and only those."""
    with tempfile.TemporaryDirectory() as root:
        os.makedirs(os.path.join(root, "docs"))
        os.makedirs(os.path.join(root, "tools"))
        open(os.path.join(root, "tools", "setup.sh"), "w").write("true\n")
        open(os.path.join(root, "CMakePresets.json"), "w").write(json.dumps(
            {"configurePresets": [{"name": "host"}], "buildPresets": [{"name": "host"}], "testPresets": [{"name": "host"}]}))
        open(os.path.join(root, "docs", "GOOD.md"), "w").write(
            "# Good doc\n\n## A `code` heading, with (punctuation)!\n\n## Twice\n\n## Twice\n\n"
            "[self](#a-code-heading-with-punctuation) [second](#twice-1) [up](../README.md#top-matter)\n"
            "`[not a link](nowhere.md)`\n\n```sh\ncat [nor](this.md)\n```\n\n"
            "<!-- runnable -->\n```sh\nsh tools/setup.sh && cmake --preset host && ctest --preset host\n```\n")
        open(os.path.join(root, "README.md"), "w").write(
            "# Top matter\n\n[good](docs/GOOD.md#twice) [gone](docs/MISSING.md) [bad anchor](docs/GOOD.md#nowhere)\n"
            "[later](docs/GOOD.md) <!-- pending -->\n[ref]: docs/ALSO_MISSING.md\n\n"
            "<!-- runnable -->\n```sh\nsh tools/nothing.sh && cmake --preset nope\n```\n")
        found = check(root, None, ["README.md", "docs/GOOD.md"])
        expected = ["README.md:3: link to docs/MISSING.md: no such file",
                    "README.md:3: link to docs/GOOD.md#nowhere: docs/GOOD.md has no heading with anchor #nowhere",
                    "README.md:4: every link on this line resolves now: remove the <!-- pending --> marker",
                    "README.md:5: link to docs/ALSO_MISSING.md: no such file",
                    "README.md:9: runnable block: tools/nothing.sh: no such file in the tree",
                    "README.md:9: runnable block: cmake --preset nope: no configure preset of that name in CMakePresets.json"]
        failures = 0
        for e in expected:
            if e not in found:
                print(f"SELF-TEST: not found: {e}")
                failures += 1
        for f in found:
            if f not in expected:
                print(f"SELF-TEST: unexpected: {f}")
                failures += 1
        print(f"check_docs self-test: {len(expected)} planted faults, {len(found)} found, {failures} wrong")
        return 1 if failures else 0


def main():
    args = sys.argv[1:]
    if args == ["--self-test"]:
        sys.exit(self_test())
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    build = None
    while args and args[0] in ("--build", "--root"):
        if len(args) < 2:
            sys.exit(f"check_docs.py: {args[0]} needs a directory")
        if args[0] == "--build":
            build = os.path.abspath(args[1])
        else:
            root = os.path.abspath(args[1])
        args = args[2:]
    docs = args or default_docs(root)
    problems = check(root, build, docs)
    for p in problems:
        print(p)
    print(f"check_docs: {len(docs)} documents, {len(problems)} problems")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""The manual (README.md and doc/*.md) stays navigable and free of development history:
every relative link and #anchor resolves (GitHub's heading slugs), README.md is at most 250
lines, each doc page opens with a sentence, and README.md, doc/, src/ and include/ carry no issue
numbers, commit hashes or history narration."""
import os
import re
import unittest

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
README = os.path.join(REPO, "README.md")
DOC = os.path.join(REPO, "doc")
MAX_README_LINES = 250

FENCE = re.compile(r"^\s*(```|~~~)")
INLINE_CODE = re.compile(r"`[^`\n]*`")
# [text](target) and ![alt](target); the text may hold brackets one level deep.
LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\[\]]*\])*\]\(([^()\s]+)(?:\s+\"[^\"]*\")?\)")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")

# History that belongs in CHANGELOG.rst and commit messages, not in the manual or the code.
ISSUE_NUMBER = re.compile(r"\bissue ?#?[0-9]+", re.IGNORECASE)
# A commit hash: 7 to 40 hex digits as a word, with at least one digit and one letter.
COMMIT_HASH = re.compile(r"\b(?=[0-9a-f]*[0-9])(?=[0-9a-f]*[a-f])[0-9a-f]{7,40}\b", re.IGNORECASE)
SESSION = re.compile(r"\bsessions?\b", re.IGNORECASE)
BEFORE_THE_WORK = re.compile(r"\bbefore the (?:[\w'-]+ ){1,4}?work\b", re.IGNORECASE)
HISTORY = {"issue number": ISSUE_NUMBER, "commit hash": COMMIT_HASH, "'session'": SESSION,
           "'before the ... work'": BEFORE_THE_WORK}
SOURCE_SUFFIXES = (".cpp", ".hpp", ".h", ".py", ".md", ".txt", ".msg", ".srv", ".cfg", ".xml",
                   ".launch", ".test", ".yaml")


def manual_pages():
    pages = [README]
    pages += sorted(os.path.join(DOC, name) for name in os.listdir(DOC) if name.endswith(".md"))
    return pages


def prose_lines(path):
    """(line number, text) of the lines outside fenced code blocks."""
    inside = False
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            if FENCE.match(line):
                inside = not inside
                continue
            if not inside:
                yield number, line.rstrip("\n")


def github_slug(heading):
    """GitHub's anchor for a heading: markup dropped, lowercase, punctuation other than '-' and
    '_' dropped, spaces to '-'."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # links keep their text
    text = text.replace("`", "").lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(path):
    """Every heading anchor of a Markdown file, with GitHub's -1, -2 suffixes for repeats."""
    seen = {}
    result = set()
    for _, line in prose_lines(path):
        match = HEADING.match(line)
        if not match:
            continue
        slug = github_slug(match.group(2))
        count = seen.get(slug, 0)
        seen[slug] = count + 1
        result.add(slug if count == 0 else "%s-%d" % (slug, count))
    for _, line in prose_lines(path):  # explicit <a id="..."> / <a name="..."> anchors
        result.update(re.findall(r"<a\s+(?:id|name)=\"([^\"]+)\"", line))
    return result


def links(path):
    """(line number, target) of every Markdown link and image outside code."""
    for number, line in prose_lines(path):
        for match in LINK.finditer(INLINE_CODE.sub("", line)):
            yield number, match.group(1)


def source_files():
    for top in ("src", "include"):
        for root, _, names in os.walk(os.path.join(REPO, top)):
            for name in sorted(names):
                if name.endswith(SOURCE_SUFFIXES):
                    yield os.path.join(root, name)


class ManualLinks(unittest.TestCase):
    def test_every_relative_link_and_anchor_resolves(self):
        broken = []
        cache = {}
        for page in manual_pages():
            for number, target in links(page):
                if re.match(r"^[a-z][a-z0-9+.-]*:", target):  # http:, https:, mailto:
                    continue
                path, _, anchor = target.partition("#")
                resolved = page if not path else os.path.normpath(
                    os.path.join(os.path.dirname(page), path))
                where = "%s:%d: %s" % (os.path.relpath(page, REPO), number, target)
                if not os.path.exists(resolved):
                    broken.append(where + " (no such file)")
                    continue
                if anchor:
                    if not resolved.endswith(".md"):
                        broken.append(where + " (an anchor into a file that is not Markdown)")
                        continue
                    if resolved not in cache:
                        cache[resolved] = anchors(resolved)
                    if anchor not in cache[resolved]:
                        broken.append(where + " (no heading with that anchor)")
        self.assertEqual(broken, [], "broken links:\n" + "\n".join(broken))

    def test_the_manual_has_the_pages_the_readme_lists(self):
        targets = {t.partition("#")[0] for _, t in links(README)}
        for name in ("node", "recipes", "method", "fabrics", "contact", "lab", "performance",
                     "testing", "known_limits", "architecture"):
            self.assertIn("doc/%s.md" % name, targets)

    def test_github_slug_rules(self):
        self.assertEqual(github_slug("Live tuning: dynamic_reconfigure"),
                         "live-tuning-dynamic_reconfigure")
        self.assertEqual(github_slug("The node: `yarn_tearing_node`"), "the-node-yarn_tearing_node")
        self.assertEqual(github_slug("Breaking-length stop"), "breaking-length-stop")


class ManualShape(unittest.TestCase):
    def test_readme_is_short(self):
        with open(README, encoding="utf-8") as f:
            lines = f.read().splitlines()
        self.assertLessEqual(len(lines), MAX_README_LINES)

    def test_each_doc_page_opens_with_a_sentence(self):
        for page in manual_pages()[1:]:
            with open(page, encoding="utf-8") as f:
                paragraphs = [p.strip() for p in re.split(r"\n\s*\n", f.read()) if p.strip()]
            name = os.path.relpath(page, REPO)
            self.assertTrue(paragraphs and paragraphs[0].startswith("# "),
                            name + ": starts with its title")
            self.assertGreater(len(paragraphs), 1, name + ": has text after its title")
            opening = paragraphs[1]
            self.assertRegex(opening, r"^[A-Z`*]", name + ": the opening paragraph is prose")
            self.assertTrue(opening.endswith("."), name + ": the opening paragraph is a sentence")


class NoHistory(unittest.TestCase):
    def check(self, paths):
        found = []
        for path in paths:
            with open(path, encoding="utf-8", errors="replace") as f:
                for number, line in enumerate(f, 1):
                    for what, pattern in HISTORY.items():
                        match = pattern.search(line)
                        if match:
                            found.append("%s:%d: %s %r" % (os.path.relpath(path, REPO), number,
                                                           what, match.group(0)))
        self.assertEqual(found, [], "history belongs in CHANGELOG.rst:\n" + "\n".join(found))

    def test_manual(self):
        self.check(manual_pages())

    def test_sources(self):
        self.check(list(source_files()))

    def test_patterns(self):
        self.assertTrue(ISSUE_NUMBER.search("see issue 12"))
        self.assertTrue(ISSUE_NUMBER.search("Issue #3"))
        self.assertTrue(COMMIT_HASH.search("main at 9b99083"))
        self.assertFalse(COMMIT_HASH.search("0x9e3779b97f4a7c15 deadbeefcafe 12345678"))
        self.assertTrue(SESSION.search("the third session"))
        self.assertTrue(BEFORE_THE_WORK.search("measured before the friction work"))
        self.assertFalse(BEFORE_THE_WORK.search("before the step works out"))


if __name__ == "__main__":
    unittest.main()

#!/usr/bin/env python3
"""Tests of scripts/check-doc-links.py, and the project's own documents checked
with it (README.md and docs/*.md: every relative link names an existing file
and heading). Registered with ctest (tests/scripts/scripts_tests.cmake)."""

import contextlib
import importlib.util
import io
import os
import subprocess
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CHECKER = os.path.join(TOP, "scripts", "check-doc-links.py")

_spec = importlib.util.spec_from_file_location("check_doc_links", CHECKER)
check_doc_links = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(check_doc_links)


class DocLinks(unittest.TestCase):
    def test_project_documents_have_no_broken_link(self):
        run = subprocess.run([sys.executable, "-B", CHECKER], capture_output=True, text=True)
        self.assertEqual(run.returncode, 0, "broken links:\n" + run.stdout + run.stderr)

    def test_slug_follows_github(self):
        # Hand-derived from GitHub's rule: punctuation such as ':', ',', '(',
        # '/', '.', '×', '→' and the en dash removed, '_' and digits kept,
        # each space a hyphen (so a removed word leaves two).
        slug = check_doc_links.slug
        self.assertEqual(slug("Session 2026-12-05, 16:03–19:03 UTC: every idea (AMD EPYC; main c9cec3b)"),
                         "session-2026-12-05-16031903-utc-every-idea-amd-epyc-main-c9cec3b")
        self.assertEqual(slug("Bar 1: ≥ 6× POV-Ray"), "bar-1--6-pov-ray")
        self.assertEqual(slug("Textures: filters and footprints (scenes/accuracy/texture_*.json)"),
                         "textures-filters-and-footprints-scenesaccuracytexture_json")
        self.assertEqual(slug("The `raylab bench limit` replay"), "the-raylab-bench-limit-replay")
        self.assertEqual(slug("main 5f7246e → 7cc52db"), "main-5f7246e--7cc52db")

    def test_broken_links_are_found(self):
        with tempfile.TemporaryDirectory() as top:
            d = os.path.join(top, "repo")  # the documents' repository; top is beside it
            os.mkdir(d)
            other = os.path.join(d, "other.md")
            with open(other, "w", encoding="utf-8") as f:
                f.write("# Title\n\n## Part\n\n## Part\n\n```\n## Not a heading\n```\n"
                        '<a id="kept"></a>\n')
            doc = os.path.join(d, "doc.md")
            with open(doc, "w", encoding="utf-8") as f:
                f.write("# Doc\n"
                        "[ok](other.md) [ok](other.md#part) [ok](other.md#part-1) [ok](other.md#kept)\n"
                        "[ok](#doc) [web](https://example.com/x#y) `[code](missing.md)`\n"
                        "[missing file](missing.md)\n"
                        "[no anchor](other.md#part-2)\n"
                        "[fenced heading](other.md#not-a-heading)\n"
                        "```\n[in a block](missing.md)\n```\n"
                        "[own anchor](#nowhere)\n"
                        "[out of the repository](../shared/NUMERICS.md)\n")
            problems = check_doc_links.check(doc, root=d)
            lines = sorted(int(p.split(":")[1]) for p in problems)
            self.assertEqual(lines, [4, 5, 6, 10], problems)
            self.assertIn("missing file", problems[0])
            self.assertEqual(len(check_doc_links.check(doc, root=top)), 5)  # ../shared inside root now
            printed = io.StringIO()
            with contextlib.redirect_stdout(printed):
                self.assertEqual(check_doc_links.main(["check-doc-links.py", doc], root=d), 1)
            self.assertEqual(printed.getvalue().strip().split("\n"), problems)


if __name__ == "__main__":
    unittest.main()

#!/usr/bin/env python3
"""scripts/check_doc_links.py: every link in README.md and docs/*.md resolves, and every
code comment citing a section names a heading that exists. The checker runs on this
repository, and on small planted trees whose one broken link or citation it must name."""
import os
import shutil
import sys
import tempfile
import textwrap
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import check_doc_links  # noqa: E402


def plant(test, files):
    """A temporary tree holding `files` (path: text), removed after `test`; returns its root."""
    root = tempfile.mkdtemp(prefix="doc-links-")
    test.addCleanup(shutil.rmtree, root)
    for path, text in files.items():
        full = os.path.join(root, path)
        os.makedirs(os.path.dirname(full), exist_ok=True)
        with open(full, "w", encoding="utf-8") as f:
            f.write(textwrap.dedent(text))
    return root


GOOD = {
    "README.md": """\
        # Tool

        ![picture](docs/picture.png) See [scenes](docs/scenes.md#light-set-up) and
        [the table](#two-commands-fresh-debian-12-clone), [a folder](docs/), [the web](https://example.org/x#y).

        ## Two commands (fresh Debian 12 clone)

        ```sh
        # Not a heading, and [not](a-link.md) a link inside a fence
        ```
        Inline code is not a link either: `[x](nowhere.md)`.
        """,
    "docs/scenes.md": """\
        # Scenes and lights

        ## Light set-up
        ### Bias
        ## Benchmarks and `check`
        ## EDTSM and EDTSM*
        Back to [the README](../README.md#tool), [bias](#bias), [check](#benchmarks-and-check),
        [edtsm](#edtsm-and-edtsm).
        """,
    "docs/picture.png": "",
    "src/code.cpp": """\
        // Scene files (docs/scenes.md "Light set-up"); the layout (README "Two commands (fresh
        // Debian 12 clone)", "Tool"); docs/scenes.md, "Bias".
        const char* help = "replay (docs/scenes.md \\"Bias\\")";
        """,
}


class Tree(unittest.TestCase):
    def problems(self, overrides):
        files = dict(GOOD)
        files.update(overrides)
        return check_doc_links.Checker(plant(self, files)).run()

    def test_this_repository_has_no_broken_link_or_citation(self):
        self.assertEqual(check_doc_links.Checker(ROOT).run(), [])

    def test_a_planted_tree_without_mistakes_passes(self):
        self.assertEqual(self.problems({}), [])

    def test_a_link_to_a_missing_file_is_named(self):
        readme = GOOD["README.md"] + "A [broken](docs/missing.md) link.\n"
        self.assertEqual(self.problems({"README.md": readme}),
                         ["README.md:12: link to docs/missing.md: no such file"])

    def test_a_missing_image_is_named(self):
        page = GOOD["docs/scenes.md"] + "![gone](gone.png)\n"
        self.assertEqual(self.problems({"docs/scenes.md": page}),
                         ["docs/scenes.md:9: link to gone.png: no such file"])

    def test_an_anchor_without_its_heading_is_named(self):
        page = GOOD["docs/scenes.md"] + "[stale](../README.md#record)\n"
        self.assertEqual(self.problems({"docs/scenes.md": page}),
                         ["docs/scenes.md:9: link to ../README.md#record: README.md has no heading whose anchor "
                          "is #record"])

    def test_an_anchor_into_the_same_page_is_checked(self):
        page = GOOD["docs/scenes.md"] + "[here](#light-setup)\n"
        self.assertEqual(len(self.problems({"docs/scenes.md": page})), 1)

    def test_a_citation_of_a_missing_heading_is_named(self):
        code = GOOD["src/code.cpp"] + '// (README "Record")\n'
        self.assertEqual(self.problems({"src/code.cpp": code}),
                         ['src/code.cpp:4: cites README.md "Record": no such heading'])

    def test_a_citation_broken_across_comment_lines_is_read_whole(self):
        code = '# see docs/scenes.md "Light\n# set-down" for why\n'
        self.assertEqual(self.problems({"scripts/x.sh": code}),
                         ['scripts/x.sh:1: cites docs/scenes.md "Light set-down": no such heading'])

    def test_every_heading_of_a_list_is_checked(self):
        code = '// (README "Tool", "Scene files")\n'
        self.assertEqual(self.problems({"src/list.h": code}),
                         ['src/list.h:1: cites README.md "Scene files": no such heading'])

    def test_a_cited_page_that_does_not_exist_is_named(self):
        code = "// the format is in docs/formats.md\n"
        self.assertEqual(self.problems({"src/f.h": code}), ["src/f.h:1: cites docs/formats.md: no such file"])

    def test_a_file_name_in_code_is_no_citation(self):
        code = 'index="$work/README.md"\nmv "$work/README.md" "$repo/README.md"\n'
        self.assertEqual(self.problems({"scripts/index.sh": code}), [])


class Slug(unittest.TestCase):
    def test_github_rules(self):
        slug = check_doc_links.slug
        self.assertEqual(slug("Two commands (fresh Debian 12 clone)"), "two-commands-fresh-debian-12-clone")
        self.assertEqual(slug("Benchmarks and `check`"), "benchmarks-and-check")
        self.assertEqual(slug("EDTSM and EDTSM*"), "edtsm-and-edtsm")
        self.assertEqual(slug("Revectorization: what the bundled scenes show"),
                         "revectorization-what-the-bundled-scenes-show")
        self.assertEqual(slug("Outside the light's frustum"), "outside-the-lights-frustum")
        self.assertEqual(slug("snake_case and  two spaces"), "snake_case-and--two-spaces")
        self.assertEqual(slug("Größe 512²"), "größe-512²")

    def test_a_repeated_heading_gets_a_number(self):
        root = plant(self, {"a.md": "# Notes\n## Notes\n## Notes\n"})
        self.assertEqual(check_doc_links.headings(os.path.join(root, "a.md"))[1], {"notes", "notes-1", "notes-2"})


if __name__ == "__main__":
    unittest.main()

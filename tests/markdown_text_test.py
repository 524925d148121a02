"""scripts/markdown_text.py: names from users' specs set into the scripts' Markdown read as
themselves (the rule of testbed/core/markdown_text.h), and a hostile label keeps a
statistics table one row per technique."""
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts"))
from markdown_text import markdown_code, markdown_text  # noqa: E402


class MarkdownText(unittest.TestCase):
    def test_text_escapes_what_would_split_a_table_or_open_markup(self):
        self.assertEqual(markdown_text("a|b"), "a\\|b")
        self.assertEqual(markdown_text("x\ny"), "x<br>y")
        self.assertEqual(markdown_text("x\r\ny"), "x<br>y")
        self.assertEqual(markdown_text("<script>"), "&lt;script>")
        self.assertEqual(markdown_text("*b* [l](u) ~s~ `c` \\"), "\\*b\\* \\[l\\](u) \\~s\\~ \\`c\\` \\\\")
        self.assertEqual(markdown_text("tab\there\x7f"), "tab here ")

    def test_underscore_between_word_characters_stays(self):
        self.assertEqual(markdown_text("smsr_2pass"), "smsr_2pass")
        self.assertEqual(markdown_text("_lead"), "\\_lead")
        self.assertEqual(markdown_text("trail_"), "trail\\_")
        self.assertEqual(markdown_text("é_x"), "é\\_x")  # as the C++ rule: ASCII letters and digits only

    def test_code_spans_fence_past_the_longest_backtick_run(self):
        self.assertEqual(markdown_code("sm"), "`sm`")
        self.assertEqual(markdown_code("a`b"), "``a`b``")
        self.assertEqual(markdown_code("`x"), "`` `x ``")
        self.assertEqual(markdown_code("a|b\nc"), "`a\\|b c`")

    def test_a_hostile_label_is_one_table_row(self):
        import corpus_cost
        rows = [{"budget": "pcf|k=3\n## x", "n": 3, "budget_cost": 1.0, "budget_error": 0.5, "best": "sm`", "best_cost": 1.0,
                 "best_error": 0.5, "scene_winner": None, "scene_winner_share": None}]
        text = corpus_cost.markdown([("frame_ms", "frame time", rows)], "rmse", {"a|b": "no receiver"}, 3)
        row = [line for line in text.splitlines() if line.startswith("| pcf")]
        self.assertEqual(len(row), 1, text)
        self.assertEqual(row[0].count(" | "), 8, row[0])  # nine cells, none split by the label
        self.assertIn("- excluded: scene a\\|b (no receiver)", text)


if __name__ == "__main__":
    unittest.main()

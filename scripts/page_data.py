"""The page data of a report page (index.html), as testbed/report/report_html.cpp writes it:
JSON inside <script type="application/json" id="page-data">. Every script that rewrites a
page's data reads and writes it here, so one escaping rule holds for all of them."""
import json
import re

PAGE_DATA = re.compile(r'(<script type="application/json" id="page-data">)(.*?)(</script>)', re.S)

# '<', '>' and '&' occur only inside JSON strings, where "\u003c" reads back the same: with
# none left, no "</script", "<!--" or "<script" can end the element or switch the HTML
# parser into its script-data escape states. U+2028/U+2029 end lines for older JavaScript.
_ESCAPES = {"<": "\\u003c", ">": "\\u003e", "&": "\\u0026", "\u2028": "\\u2028", "\u2029": "\\u2029"}
_UNSAFE = re.compile("[<>&\u2028\u2029]")


def script_safe_json(data):
    """`data` as JSON text that can stand inside a <script> element."""
    return _UNSAFE.sub(lambda m: _ESCAPES[m.group(0)], json.dumps(data, ensure_ascii=False))

#!/usr/bin/env python3
"""tools/difftest.py's reducer keeps exactly the lines a difference needs,
and the % marks."""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tools"))
import difftest  # noqa: E402

text = "%\nO1000\n#1 = 1\nKEY1\n#2 = 2\n#3 = 3\nKEY2\nM30\n%\n"
small = difftest.reduce(text, lambda t: "KEY1" in t and "KEY2" in t)
if small != "%\nKEY1\nKEY2\n%\n":
    sys.exit(f"reduced to:\n{small}")
untouched = difftest.reduce(text, lambda t: t == text)
if untouched != text:
    sys.exit(f"removed lines a difference needs:\n{untouched}")
print("reduce: ok")

"""docs/python.md's example runs as written: its ```python blocks, in order, in one namespace,
from the repository's root."""
import os
import re


def test_the_worked_example_runs(repo):
    text = (repo / "docs" / "python.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert len(blocks) >= 2
    namespace = {}
    cwd = os.getcwd()
    os.chdir(repo)
    try:
        for block in blocks:
            exec(compile(block, "docs/python.md", "exec"), namespace)
    finally:
        os.chdir(cwd)
    assert not namespace["report"]["pass"]

"""docs/model-file.md matches the loader: every YAML block of the page is a complete model file
that loads (or, when it starts with ``# refused: <message>``, fails with that message), and every
key the loader accepts is documented, with an example that uses it."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

import hpgen
from hpgen.errors import ModelError
from hpgen.model import load_model_text
from hpgen.model.loader import INTEGRATOR_KEYS, TOP_KEYS
from hpgen.model.scene import INITIAL_KEYS, SCENE_KEYS

PAGE = Path(hpgen.__file__).resolve().parents[1] / "docs" / "model-file.md"
BLOCKS = re.findall(r"```yaml\n(.*?)```", PAGE.read_text(), re.S)


def _refused(block):
    first = block.splitlines()[0]
    return first.split("# refused:", 1)[1].strip() if first.startswith("# refused:") else None


@pytest.mark.parametrize("k", range(len(BLOCKS)))
def test_every_yaml_block_loads_or_fails_as_the_page_says(k):
    block, expected = BLOCKS[k], _refused(BLOCKS[k])
    if expected is None:
        model = load_model_text(block, f"model-file.md block {k}")
        assert model.name
    else:
        with pytest.raises(ModelError) as info:
            load_model_text(block, "bad.yaml")
        assert expected in str(info.value), str(info.value)


def test_every_key_is_documented_with_an_example():
    page = PAGE.read_text()
    loading = [b for b in BLOCKS if _refused(b) is None]
    keys_table = page.split("Top-level keys")[1].split("## group")[0]
    for key in TOP_KEYS:
        assert f"| `{key}` |" in keys_table, key
        if key != "schema":
            assert any(re.search(rf"^{key}:", b, re.M) for b in loading), key
    assert "schema: 1" in BLOCKS[0]
    for key in SCENE_KEYS + INITIAL_KEYS + INTEGRATOR_KEYS:
        assert f"`{key}`" in page, key
    for form in ("rotvec", "quat", "angle", "position", "every_t"):
        assert f"{form}:" in page, form
    assert "any other key is an error" in page.replace("\n", " ")


def test_no_h_positive_rule_is_left():
    page = PAGE.read_text()
    assert "h` > 0" not in page and "h < 0 runs backwards" in page.replace("**", "")

"""The shared YAML loaders: a key given twice is an error naming it and both lines."""

import pytest
import yaml
from rosbook_env.yaml_files import DuplicateKeyError, YamlCppLoader, load_unique


def test_a_duplicate_key_names_the_key_and_both_lines():
    text = "image: m.pgm\nresolution: 0.05\nnegate: 0\nresolution: 0.1\n"
    with pytest.raises(DuplicateKeyError, match=r"key 'resolution' given twice \(lines 2 and 4\)"):
        load_unique(text)
    with pytest.raises(yaml.YAMLError):  # callers that catch YAML errors catch this one too
        load_unique(text, YamlCppLoader)


def test_duplicates_in_nested_mappings_and_lists_of_mappings():
    with pytest.raises(DuplicateKeyError, match="'x'"):
        load_unique("waypoints:\n  - {x: 1, y: 2, x: 3}\n")
    with pytest.raises(DuplicateKeyError, match="'pose'"):
        load_unique("boxes:\n  - pose: [0, 0, 0]\n    pose: [1, 1, 0]\n")


def test_unique_keys_merges_and_numbers_load_as_before():
    text = "base: &b {a: 1, b: 2}\nderived:\n  <<: *b\n  b: 3\n"
    assert load_unique(text)["derived"] == {"a": 1, "b": 3}  # a merge may be overridden
    assert load_unique("r: 5e-2\n") == {"r": "5e-2"}  # PyYAML's YAML 1.1, as safe_load
    assert load_unique("r: 5e-2\n", YamlCppLoader) == {"r": 0.05}  # yaml-cpp's reading
    assert load_unique("a: 1\nb: [1, 1]\n") == {"a": 1, "b": [1, 1]}
    assert load_unique("") is None

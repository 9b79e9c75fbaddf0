"""YAML loaders for the files our Python reads (map YAMLs, world files, tuning files,
waypoints): PyYAML's safe loader, except that a key given twice in one mapping is an error
naming the key and both lines. PyYAML (and yaml-cpp) would keep the last silently, so a
`resolution:` pasted below an old one changes the map without a word."""

import re

import yaml

MERGE_TAG = "tag:yaml.org,2002:merge"


class DuplicateKeyError(yaml.YAMLError):
    """A mapping gives one key twice; str() names the key and the lines."""

    def __init__(self, key, first_line, line):
        super().__init__(
            f"key {key!r} given twice (lines {first_line} and {line}); keep one of them"
        )
        self.key = key


class UniqueKeyLoader(yaml.SafeLoader):
    """yaml.SafeLoader that refuses a duplicate key (DuplicateKeyError, a yaml.YAMLError).
    Keys brought in by a merge (`<<: *base`) may be overridden, as YAML intends."""

    def construct_mapping(self, node, deep=False):
        if isinstance(node, yaml.MappingNode):
            seen = {}
            for key_node, _ in node.value:
                if key_node.tag == MERGE_TAG:
                    continue
                key = self.construct_object(key_node, deep=True)
                try:
                    first = seen.setdefault(key, key_node)
                except TypeError:  # an unhashable key: SafeLoader's own error follows
                    continue
                if first is not key_node:
                    raise DuplicateKeyError(
                        key, first.start_mark.line + 1, key_node.start_mark.line + 1
                    )
        return super().construct_mapping(node, deep=deep)


class YamlCppLoader(UniqueKeyLoader):
    """UniqueKeyLoader that also reads `5e-2` and `1e3` as numbers, as YAML 1.2 and the C++
    nodes' yaml-cpp do (PyYAML's YAML 1.1 floats need a dot: it read `5e-2` as text). For the
    files a C++ node reads too: map YAMLs and world files."""


YamlCppLoader.add_implicit_resolver(
    "tag:yaml.org,2002:float",
    re.compile(r"^[-+]?(?:[0-9][0-9_]*)(?:\.[0-9_]*)?[eE][-+]?[0-9]+$"),
    list("-+0123456789"),
)


def load_unique(stream, loader=UniqueKeyLoader):
    """yaml.load with duplicate keys refused (DuplicateKeyError, a yaml.YAMLError)."""
    return yaml.load(stream, Loader=loader)

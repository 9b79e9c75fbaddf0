import argparse
import os

import pytest
from rosbook_cli import checks


@pytest.mark.parametrize("text", ["nan", "inf", "-inf", "abc", ""])
def test_finite_float_refuses_what_is_not_a_finite_number(text):
    with pytest.raises(argparse.ArgumentTypeError):
        checks.finite_float(text)


def test_ranges():
    assert checks.finite_float("-2.5") == -2.5
    assert checks.positive_float("3") == 3.0
    assert checks.non_negative_float("0") == 0.0
    for bad in ("0", "-1"):
        with pytest.raises(argparse.ArgumentTypeError, match="greater than 0"):
            checks.positive_float(bad)
    with pytest.raises(argparse.ArgumentTypeError, match="0 or more"):
        checks.non_negative_float("-0.1")


def test_output_problems_name_the_folder_and_the_fix(tmp_path):
    assert checks.output_folder_problem(tmp_path / "a b#é.png") is None
    assert "mkdir -p" in checks.output_folder_problem(tmp_path / "missing" / "x.png")
    assert "is a folder" in checks.output_folder_problem(tmp_path)
    assert "not a file name" in checks.output_folder_problem("")


@pytest.mark.skipif(os.geteuid() == 0, reason="root may write anywhere")
def test_unwritable_folder(tmp_path):
    tmp_path.chmod(0o500)
    assert "not writable" in checks.output_folder_problem(tmp_path / "x.png")


def test_output_folder_is_created_or_refused(tmp_path):
    checks.require_output_folder("tool", tmp_path / "new" / "out dir")
    assert (tmp_path / "new" / "out dir").is_dir()
    (tmp_path / "file").write_text("x")
    with pytest.raises(SystemExit, match="tool: cannot create the output folder"):
        checks.require_output_folder("tool", tmp_path / "file" / "sub")

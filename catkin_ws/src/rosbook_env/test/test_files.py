import os

from rosbook_env.files import special_file_note


def test_regular_files_folders_and_missing_paths_are_not_special(tmp_path):
    regular = tmp_path / "map.yaml"
    regular.write_text("image: map.pgm\n")
    assert special_file_note(regular) is None
    assert special_file_note(tmp_path) is None
    assert special_file_note(tmp_path / "missing.yaml") is None
    assert special_file_note("bad\0name") is None


def test_devices_and_pipes_are_refused_with_the_reason(tmp_path):
    assert "not a regular file" in special_file_note("/dev/zero")
    pipe = tmp_path / "pipe.yaml"
    os.mkfifo(pipe)
    assert "not a regular file" in special_file_note(pipe)

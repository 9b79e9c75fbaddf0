import os

from rosbook_env.files import (
    looked_in_note,
    resolve_user_path,
    shell_folder,
    special_file_note,
)


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


def launched_from(monkeypatch, tmp_path):
    """What roslaunch does: the node runs in ~/.ros (here `ros_home`), $PWD stays the shell's."""
    shell, ros_home = tmp_path / "shell", tmp_path / "ros_home"
    shell.mkdir()
    ros_home.mkdir()
    monkeypatch.chdir(ros_home)
    monkeypatch.setenv("PWD", str(shell))
    monkeypatch.setenv("ROS_HOME", str(ros_home))
    return shell, ros_home


def test_relative_path_missing_from_cwd_is_found_in_the_shell_folder(monkeypatch, tmp_path):
    shell, _ = launched_from(monkeypatch, tmp_path)
    (shell / "mymap.yaml").write_text("image: mymap.pgm\n")
    assert shell_folder() == str(shell)
    assert resolve_user_path("mymap.yaml") == str(shell / "mymap.yaml")
    assert resolve_user_path(shell / "mymap.yaml") == str(shell / "mymap.yaml")


def test_the_cwd_wins_and_absolute_paths_stay(monkeypatch, tmp_path):
    shell, ros_home = launched_from(monkeypatch, tmp_path)
    (shell / "m.yaml").write_text("a")
    (ros_home / "m.yaml").write_text("b")
    assert resolve_user_path("m.yaml") == "m.yaml"
    assert resolve_user_path("/nowhere/m.yaml") == "/nowhere/m.yaml"
    assert resolve_user_path("") == ""


def test_found_nowhere_comes_back_as_given_and_the_note_names_both_folders(monkeypatch, tmp_path):
    shell, ros_home = launched_from(monkeypatch, tmp_path)
    assert resolve_user_path("gone.yaml") == "gone.yaml"
    note = looked_in_note("gone.yaml")
    assert str(ros_home) in note and str(shell) in note
    assert "map_file:=$(pwd)/mymap.yaml" in note
    assert looked_in_note(shell / "gone.yaml") == ""


def test_a_file_to_write_goes_to_the_shell_folder(monkeypatch, tmp_path):
    shell, ros_home = launched_from(monkeypatch, tmp_path)
    (ros_home / "data.bag").write_text("old")  # an earlier run's bag in ~/.ros is not reused
    assert resolve_user_path("data.bag", for_writing=True) == str(shell / "data.bag")


def test_without_a_distinct_shell_folder_paths_stay_as_given(monkeypatch, tmp_path):
    monkeypatch.chdir(tmp_path)
    for pwd in (str(tmp_path), "", "relative/dir", str(tmp_path / "missing")):
        monkeypatch.setenv("PWD", pwd)
        assert shell_folder() is None
        assert resolve_user_path("x.yaml") == "x.yaml"
        assert resolve_user_path("x.bag", for_writing=True) == "x.bag"
    monkeypatch.setenv("ROS_HOME", str(tmp_path / "ros_home"))
    # A shell in its own folder: the name is wrong, the folder is not the problem.
    assert looked_in_note("x.yaml") == f" (looked in {tmp_path})"

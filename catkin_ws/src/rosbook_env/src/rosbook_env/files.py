"""Checks on files a user names, shared by the nodes that read them."""

import os
import stat


def special_file_note(path):
    """Why `path` must not be read, for a device, FIFO or socket (else None): /dev/zero
    would be read until memory runs out, a FIFO would block forever. A missing file or a
    folder gives None: opening it raises the error the callers already name."""
    try:
        mode = os.stat(path).st_mode
    except (OSError, ValueError):
        return None
    if stat.S_ISREG(mode) or stat.S_ISDIR(mode):
        return None
    return "not a regular file (a device or a pipe)"


# The fix a "not found" error names: roslaunch runs nodes in ~/.ros, so a path the user typed
# is safest absolute, and $(pwd) makes one from the shell they are in.
ABSOLUTE_PATH_FIX = "give an absolute path, e.g. map_file:=$(pwd)/mymap.yaml"


def shell_folder():
    """The folder of the shell that started this process, when it is not the cwd: roslaunch
    runs its nodes in ~/.ros (ROS_HOME) but passes $PWD on unchanged, so a relative
    `map_file:=mymap.yaml` or `bag:=data.bag` meant the shell's folder. None when $PWD is
    unset, not an absolute folder, or the cwd itself (a shell or rosrun in that folder)."""
    pwd = os.environ.get("PWD", "")
    if not os.path.isabs(pwd) or not os.path.isdir(pwd):
        return None
    try:
        if os.path.samefile(pwd, os.getcwd()):
            return None
    except OSError:
        return None
    return pwd


def resolve_user_path(path, for_writing=False):
    """Where a file the user named is: an absolute path as given; a relative one as given
    when it exists from the cwd, else from the shell's folder ($PWD, see shell_folder) when
    it exists there. For a file to write (for_writing) a relative path always means the
    shell's folder, where the user will look for it. A file found nowhere comes back as given,
    so the caller's open raises its own error (with `looked_in_note` saying where)."""
    text = os.fspath(path)
    if not text or os.path.isabs(text):
        return text
    shell = shell_folder()
    if shell is None:
        return text
    in_shell = os.path.join(shell, text)
    if for_writing:
        return in_shell
    if os.path.lexists(text) or not os.path.lexists(in_shell):
        return text
    return in_shell


def looked_in_note(path, fix=ABSOLUTE_PATH_FIX):
    """For a relative path found nowhere: the folders resolve_user_path looked in and the fix,
    as " (looked in A and B; give an absolute path, ...)"; the fix is left out where the cwd
    is the shell's own folder (not roslaunch's ~/.ros). Empty for an absolute path."""
    text = os.fspath(path)
    if os.path.isabs(text):
        return ""
    folders = [os.getcwd()]
    shell = shell_folder()
    if shell is not None:
        folders.append(shell)
    ros_home = os.environ.get("ROS_HOME") or os.path.expanduser("~/.ros")
    if shell is None and os.path.realpath(folders[0]) != os.path.realpath(ros_home):
        return f" (looked in {folders[0]})"  # a shell's own folder: the name is wrong
    return f" (looked in {' and '.join(folders)}; {fix})"

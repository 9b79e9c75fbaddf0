"""One benchmark's section of bench/RESULTS.md, rewritten in place (shared by the bench_*
scripts that keep their own section)."""

from pathlib import Path


def write_section(path, lines):
    """Put `lines` (starting with the section's heading) into the markdown file `path`,
    replacing that section if it is there (up to the next '## ' heading), else at the end;
    other sections are kept as they are. Written atomically (a temporary file, renamed)."""
    path = Path(path)
    text = path.read_text() if path.exists() else ""
    old = text.splitlines()
    body = [*lines, ""]
    if lines[0] in old:
        start = old.index(lines[0])
        end = next(
            (i for i in range(start + 1, len(old)) if old[i].startswith("## ")),
            len(old),
        )
        new = old[:start] + body + old[end:]
    else:
        new = old + ([""] if old and old[-1] != "" else []) + body
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text("\n".join(new).rstrip("\n") + "\n")
    tmp.replace(path)

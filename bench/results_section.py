"""One benchmark's section of bench/RESULTS.md, rewritten in place (shared by the bench_*
scripts that keep their own section)."""

from pathlib import Path


def _trimmed(lines):
    """`lines` without blank lines at either end."""
    lines = list(lines)
    while lines and not lines[0].strip():
        lines.pop(0)
    while lines and not lines[-1].strip():
        lines.pop()
    return lines


def split_subsections(lines):
    """(preamble, [(heading, body)]) of a section's lines at its '### ' headings: the
    preamble is everything before the first one (the '## ' heading included)."""
    preamble, subsections = [], []
    for line in lines:
        if line.startswith("### "):
            subsections.append((line, []))
        elif subsections:
            subsections[-1][1].append(line)
        else:
            preamble.append(line)
    return preamble, subsections


def merge_subsections(old, new):
    """The section `new` (lines), keeping the '### ' subsections of `old` that `new` does not
    bring: a run that measured some cases (one laser, say) replaces only their subsections.
    Kept subsections stay where they were; new ones follow in `new`'s order."""
    _, old_subs = split_subsections(old)
    preamble, new_subs = split_subsections(new)
    brought = dict(new_subs)
    merged = [(h, brought.pop(h) if h in brought else body) for h, body in old_subs]
    merged += [(h, body) for h, body in new_subs if h in brought]
    out = _trimmed(preamble)
    for heading, body in merged:
        body = _trimmed(body)
        out += ["", heading, *([""] + body if body else [])]
    return out


def write_section(path, lines, keep_subsections=False):
    """Put `lines` (starting with the section's heading) into the markdown file `path`,
    replacing that section if it is there (up to the next '## ' heading), else at the end;
    other sections are kept as they are. With `keep_subsections`, the section's '### '
    subsections that `lines` does not bring are kept (merge_subsections). Written atomically
    (a temporary file, renamed)."""
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
        if keep_subsections:
            body = [*merge_subsections(old[start:end], lines), ""]
        new = old[:start] + body + old[end:]
    else:
        new = old + ([""] if old and old[-1] != "" else []) + body
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text("\n".join(new).rstrip("\n") + "\n")
    tmp.replace(path)

"""Release order, the one rule every view, table and request follows for the builds of one engine: by the release
parsed into numbers (2021.9.29.2 before 2021.10.1, which a string sort inverts), never by the order builds were
found, asked for or finished."""
import re

PARTS = re.compile(r"[0-9]+|[A-Za-z]+")


def release_key(version):
    """A sort key of a release as spelled ('2023.8.2.3', '10.4.4', '2023.02a'): its numbers as numbers, letters after
    the numbers they follow; a version without a number ('unknown', '') after every release that has one."""
    parts = tuple((0, int(p)) if p.isdigit() else (1, p) for p in PARTS.findall(str(version or "")))
    return (0, parts) if parts and parts[0][0] == 0 else (1, parts)


def in_release_order(names):
    """Engine names with the builds of each engine (`code@version`) in release order, each in a place one of its
    builds held; every other name keeps its place."""
    names = list(names)
    builds = {}
    for name in names:
        code, at, version = name.partition("@")
        if at:
            builds.setdefault(code, []).append(name)
    ordered = {code: iter(sorted(group, key=lambda n: release_key(n.partition("@")[2]))) for code, group in
               builds.items()}
    return [next(ordered[name.partition("@")[0]]) if "@" in name else name for name in names]


def release_text(name):
    """An engine name as text that sorts in release order ('lammps@2021.9.29.2' before 'lammps@2021.10.1'): the
    release_key of its build, numbers zero-padded; for SQL (the campaign's views), where a string sort decides."""
    code, at, version = str(name or "").partition("@")
    if not at:
        return code
    group, parts = release_key(version)
    return f"{code}@{group}" + "".join(f".{kind}{value:020d}" if kind == 0 else f".{kind}{value}"
                                       for kind, value in parts)

"""LAMMPS releases as harness spells them: the banner's '29 Sep 2021 - Update 2' is '2021.9.29.2' (YYYY.M.D, then .U
for a stable update), with a tuple that orders them; the releases whose dialect was checked against the binary, the
nearest of them for any other, and the one-line note a report gives for a release that was not checked. What harness
says of a release holds for those it checked alone: a range of them is written first to last
('2023.8.2.3 to 2025.7.22.4'), never open towards releases it has not run."""
import re

MONTHS = {name: number for number, name in enumerate(
    ("Jan", "Feb", "Mar", "Apr", "May", "Jun", "Jul", "Aug", "Sep", "Oct", "Nov", "Dec"), start=1)}
BANNER = re.compile(r"Simulator - ([0-9]+) ([A-Za-z]+) ([0-9]+)(?: - Update ([0-9]+))?\s*$", re.MULTILINE)
VERIFIED = ((2021, 9, 29, 2), (2022, 6, 23, 4), (2023, 8, 2, 3), (2024, 8, 29, 3), (2025, 7, 22, 4))
DEFAULT = VERIFIED[0]       # Debian 12's: the dialect of a binary whose release cannot be read (or of none)
NEWEST = VERIFIED[-1]       # the last release checked: every range of an ingredient ends at one checked


def release(text):
    """(spelling, tuple) of the release in the banner `lmp -h` prints, e.g. ('2021.9.29.2', (2021, 9, 29, 2)); None
    when the banner names none."""
    match = BANNER.search(text or "")
    if not match or match.group(2)[:3].title() not in MONTHS:
        return None
    day, month, year, update = match.groups()
    numbers = (int(year), MONTHS[month[:3].title()], int(day)) + ((int(update),) if update else ())
    return spelled(numbers), numbers


def spelled(numbers):
    return ".".join(str(n) for n in numbers)


def parsed(version):
    """The tuple of a spelled release ('2023.8.2.3' -> (2023, 8, 2, 3)); None for 'unknown' or another spelling."""
    parts = str(version or "").split(".")
    return tuple(int(p) for p in parts) if len(parts) in (3, 4) and all(p.isdigit() for p in parts) else None


def nearest(version):
    """The checked release nearest to `version` by date (the older one on a tie); Debian 12's for an unreadable one."""
    numbers = parsed(version)
    if numbers is None:
        return DEFAULT
    return min(VERIFIED, key=lambda r: (abs(day_number(r) - day_number(numbers)), r > numbers, r))


def day_number(numbers):
    year, month, day = numbers[:3]
    return year * 372 + month * 31 + day + (numbers[3] if len(numbers) > 3 else 0) / 100.0


def dialect_note(version):
    """'' for a release whose dialect was checked against its binary; else the one-line reason a report prints."""
    numbers = parsed(version)
    if numbers in VERIFIED:
        return ""
    closest = spelled(nearest(version))
    if numbers is None:
        return f"LAMMPS version {version!r} unreadable: checked against Debian 12's dialect ({closest})"
    return f"LAMMPS {version} was never checked: checked against the nearest dialect ({closest})"


def holds(ranges, version):
    """The choice whose (first, last, choice) range of checked releases holds the nearest checked release of
    `version`."""
    numbers = nearest(version)
    for first, last, choice in ranges:
        if first <= numbers <= last:
            return choice
    raise LookupError(f"no range holds {spelled(numbers)}")


def checked(first=DEFAULT, last=NEWEST):
    """'2023.8.2.3 to 2025.7.22.4': releases harness checked, first to last (one release: itself)."""
    return spelled(first) if first == last else f"{spelled(first)} to {spelled(last)}"

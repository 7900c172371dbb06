"""The campaign file's schema: every key with the type it takes, checked over the whole file before anything is
built, so that a mistake is one line naming the key, what it holds and what was expected. Numbers come back as
floats (whole numbers for counts), so that `angles = [10]` and `--angles 10` are the same request."""
import datetime
import math

from ...engines import ENGINES
from ...infra.errors import UserError
from ...runs.request import TARGETS
from ...scenes.scene import WALLS
from .limits import MAX_LIST


class Mistake(Exception):
    """Where in the file (a key path) and what is wrong there."""

    def __init__(self, where, text):
        super().__init__(where, text)
        self.where, self.text = where, text


def shown(value):
    """A value as the file wrote it, in TOML's words, cut to a readable length."""
    if isinstance(value, bool):
        return f"a boolean ({str(value).lower()})"
    if isinstance(value, int):
        return f"an integer ({value})"
    if isinstance(value, float):
        return f"a float ({value:g})"
    if isinstance(value, str):
        text = value if len(value) <= 40 else value[:37] + "..."
        return f"a string ({text!r})"
    if isinstance(value, list):
        return f"an array of {len(value)}"
    if isinstance(value, dict):
        return "a table"
    if isinstance(value, (datetime.date, datetime.time)):
        return "a date or time"
    return type(value).__name__


class Number:
    """A finite number (an integer is taken as the float it names)."""
    expected = "a number"

    def __call__(self, value, where):
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise Mistake(where, f"is {shown(value)}; expected {self.expected}")
        if not math.isfinite(value):
            raise Mistake(where, f"is {value}; expected a finite number")
        return float(value)


class Whole:
    """A whole number of at least `low`."""

    def __init__(self, low=1):
        self.low = low
        self.expected = f"a whole number >= {low}"

    def __call__(self, value, where):
        if isinstance(value, bool) or not isinstance(value, int):
            raise Mistake(where, f"is {shown(value)}; expected {self.expected}")
        if value < self.low:
            raise Mistake(where, f"is {value}; expected {self.expected}")
        return value


class Text:
    """A string, one of `choices` when given."""

    def __init__(self, choices=None):
        self.choices = choices          # read when checked: a registry may gain an entry (an engine) after import

    @property
    def expected(self):
        return f"one of {', '.join(self.choices)}" if self.choices else "a string"

    def __call__(self, value, where):
        if not isinstance(value, str) or (self.choices and value not in self.choices):
            raise Mistake(where, f"is {shown(value)}; expected {self.expected}")
        return value


class EngineName(Text):
    """An engine's name, or one of its builds: `lammps@2023.8.2`, `lammps@all`, `lammps@/path/to/lmp`."""

    def __call__(self, value, where):
        code = value.partition("@")[0] if isinstance(value, str) else value
        super().__call__(code, where)
        return value


class Boolean:
    """true or false."""
    expected = "true or false"

    def __call__(self, value, where):
        if not isinstance(value, bool):
            raise Mistake(where, f"is {shown(value)}; expected {self.expected}")
        return value


class Either:
    """The first of several types that takes the value."""

    def __init__(self, *types, expected=None):
        self.types = types
        self.expected = expected or " or ".join(t.expected for t in types)

    def __call__(self, value, where):
        for kind in self.types:
            try:
                return kind(value, where)
            except Mistake as mistake:
                if mistake.where != where:       # the value was of this type, a part of it is wrong
                    raise
        raise Mistake(where, f"is {shown(value)}; expected {self.expected}")


class ListOf:
    """A non-empty array (unless `empty`) of at most MAX_LIST items of one type."""

    def __init__(self, item, expected, empty=False):
        self.item, self.expected, self.empty = item, expected, empty

    def __call__(self, value, where):
        if not isinstance(value, list):
            raise Mistake(where, f"is {shown(value)}; expected {self.expected}")
        if not value and not self.empty:
            raise Mistake(where, f"is empty; expected {self.expected}")
        if len(value) > MAX_LIST:
            raise Mistake(where, f"has {len(value)} items; at most {MAX_LIST} are taken")
        return [self.item(v, f"{where}[{i}]") for i, v in enumerate(value)]


class Table:
    """A table of known keys, each of its type; `required` keys must be there."""

    def __init__(self, fields, required=(), expected="a table"):
        self.fields, self.required, self.expected = fields, tuple(required), expected

    def __call__(self, value, where):
        if not isinstance(value, dict):
            raise Mistake(where, f"is {shown(value)}; expected {self.expected}")
        unknown = sorted(set(value) - set(self.fields))
        if unknown:
            raise Mistake(f"{where}.{unknown[0]}" if where else unknown[0],
                          f"is an unknown key{' of ' + where if where else ''}; known: "
                          f"{', '.join(sorted(self.fields))}")
        missing = [key for key in self.required if key not in value]
        if missing:
            raise Mistake(where, f"has no {missing[0]}; expected {self.expected}")
        return {key: self.fields[key](v, f"{where}.{key}" if where else key) for key, v in value.items()}


class TableOf:
    """A table whose keys are free (or among `keys`) and whose values are all of one type."""

    def __init__(self, value, keys=None, expected="a table"):
        self.value, self.keys, self.expected = value, Text(keys) if keys else Text(), expected

    def __call__(self, value, where):
        if not isinstance(value, dict):
            raise Mistake(where, f"is {shown(value)}; expected {self.expected}")
        for key in value:
            self.keys(key, f"{where}.{key}")
        return {key: self.value(v, f"{where}.{key}") for key, v in value.items()}


MATERIAL = Either(Text(), Table({"material": Text(), "radius": Number(), "E": Number(), "nu": Number(),
                                 "rho": Number(), "mu": Number()}),
                  expected="a preset name or a table of radius, E, nu, rho, mu")
NUMBERS = ListOf(Number(), "an array of numbers, e.g. [0.5, 0.9]")
FILE = Table({
    "name": Text(),
    "laws": ListOf(Text(), 'an array of law names, e.g. ["thornton"]', empty=True),
    "variants": ListOf(Table({"law": Text(), "with": TableOf(Text(), expected="a table of KEY = \"VALUE\"")},
                             required=("law",), expected='a table with law = "..." and with = {KEY = "VALUE"}'),
                       "an array of tables: [[variants]] with law = ... and with = {KEY = VALUE}"),
    "engines": ListOf(EngineName(ENGINES), f"an array of engine names ({', '.join(ENGINES)}, or ENGINE@VERSION)"),
    "engine_options": TableOf(TableOf(Text(), expected='a table of KEY = "VALUE"'), keys=ENGINES,
                              expected="a table of engines"),
    "engine_inputs": TableOf(Text(), keys=ENGINES, expected='a table of ENGINE = "your own input"'),
    "e_n": NUMBERS, "angles": NUMBERS, "psi": NUMBERS, "vt": NUMBERS, "speeds": NUMBERS, "normal_speeds": NUMBERS,
    "spins": NUMBERS, "dt": NUMBERS, "mus": NUMBERS, "radii": NUMBERS,
    "walls": ListOf(Text(WALLS), f"an array of walls ({', '.join(WALLS)})"),
    "targets": ListOf(Text(TARGETS), f"an array of targets ({', '.join(TARGETS)})"),
    "materials": ListOf(MATERIAL, "an array of preset names or tables, e.g. [\"tcc13\", {radius = 0.01, E = 1e9, "
                                  "nu = 0.3, rho = 2500, mu = 0.3}]"),
    "steps_per_contact": ListOf(Whole(), "an array of whole numbers >= 1, e.g. [1000]"),
    "converged": Boolean(),
    "block": Whole(),
})


def validated(data, name):
    """The file's table checked against the schema, numbers as floats; UserError naming the first mistake."""
    try:
        return FILE(data, "")
    except Mistake as mistake:
        raise UserError(f"campaign {name}: {mistake.where} {mistake.text}") from None

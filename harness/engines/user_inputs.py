"""Engine inputs as the engine takes them (`--engine-input ENGINE=TEXT`, `engine_input=` in Python): the text a user
writes in that engine, read by the engine's own vocabulary (harness/engines/<engine>/inputs.py, registered in
harness/engines/inputs.py), refused with the engine's words or flagged where unphysical, and composed of neutral
sub-models with the input's numbers (docs/user-guide.md#your-own-engine-inputs). It reaches an engine as its option
`input`, so that its dialect, its deck, the run's key and the records all carry it."""
import importlib
import os
from dataclasses import dataclass

from ..infra.errors import UserError

INPUT_OPTION = "input"          # the engine option an input travels in (Engine.dialect, the decks, run.json)


def refuse(engine, reason):
    """An input its engine would refuse, with the engine's reason."""
    raise UserError(f"{engine} would refuse this input: {reason}")


@dataclass(frozen=True)
class Flag:
    """A value its engine takes but that is unphysical: the input runs, and this is said beside its results."""
    name: str
    why: str


@dataclass(frozen=True)
class EngineInput:
    """An input as parsed: its engine, its text verbatim, its words (numbers as floats), its friction coefficient.
    An engine's subclass composes it (composition(target, version)), names its paper law (law_family()), flags its
    unphysical values (flags(version)) and gives the deck its words (deck_style())."""
    engine: str
    text: str
    tokens: tuple
    mu: float | None = None

    def law_family(self):
        raise NotImplementedError

    def flags(self, version=None):
        return ()

    def check_release(self, version):
        """Itself, or a refusal of release `version` in its own words."""
        return self

    def composition(self, target, version=None):
        raise NotImplementedError

    def translations(self, target, version=None):
        """Other inputs of its engine that compute the same composition on `target` in `version` (those a
        vocabulary proposes, kept where their composition is this one's)."""
        mine = self.composition(target, version).describe()
        module = vocabulary(self.engine)
        out = []
        for text in self.alternatives():
            try:
                other = module.parse(text, version)
                if other.composition(target, version).describe() == mine:
                    out.append(other.text)
            except UserError:
                continue
        return out

    def other_engines(self, contact):
        """[(engine, text, release)] of inputs of other engines that may compute the same law on this contact
        (studies/explain.py keeps those whose composition, stepped as this one, gives the same rebounds)."""
        return []

    def alternatives(self):
        """Texts of its engine that may compute what it computes (translations() keeps those that do)."""
        return []

    def neutral(self, target="wall", version=None):
        """{sub-model key: label} of the composition it maps to (what results and reports record beside the text)."""
        return self.composition(target, version).describe()


def vocabulary(engine):
    """The inputs module of `engine` (its code, without @build), or a refusal naming those that have one."""
    from .inputs import VOCABULARIES
    code = engine.partition("@")[0]
    if code not in VOCABULARIES:
        raise UserError(f"harness reads no {code} input yet; it reads inputs of {', '.join(VOCABULARIES)}")
    return importlib.import_module(VOCABULARIES[code], "harness.engines")


def parse(engine, text, version=None):
    """The EngineInput of `text` for `engine` (the words, or @FILE: the contact lines of a deck or script)."""
    module = vocabulary(engine)
    text = read_file(module, text[1:]) if text.startswith("@") else text
    if not text.strip():
        raise UserError(f"--engine-input {engine}= gives no text")
    parsed = module.parse(" ".join(text.split()), version)
    return parsed.check_release(version) if version else parsed


def read_file(module, path):
    """The contact text of a deck or script at `path`, as the engine's vocabulary finds it there."""
    if not os.path.isfile(path):
        raise UserError(f"--engine-input @{path}: no such file")
    try:
        with open(path, encoding="utf-8") as handle:
            return module.contact_text(handle.read(), path)
    except (OSError, UnicodeDecodeError) as exc:
        raise UserError(f"--engine-input @{path}: cannot read it ({exc.__class__.__name__})") from None


def split_argument(item):
    """'ENGINE=TEXT' -> (engine, text), one line for another form."""
    engine, sep, text = str(item).partition("=")
    if not sep or not engine.strip():
        raise UserError(f"--engine-input takes ENGINE=TEXT (e.g. lammps='hooke 1e6 0.5 tangential linear_history "
                        f"2.8e5 0.5 0.4'), got {item!r}")
    return engine.strip(), text.strip()


def engine_inputs_from(items):
    """{engine: text} of --engine-input ENGINE=TEXT items (or an API dict), each parsed once (refused here, before
    anything runs); an engine given twice is refused."""
    pairs = list(items.items()) if isinstance(items, dict) else [split_argument(i) for i in (items or ())]
    out = {}
    for engine, text in pairs:
        if engine in out:
            raise UserError(f"--engine-input for {engine} given twice")
        if not isinstance(text, str):
            raise UserError(f"engine_input for {engine} must be text, got {type(text).__name__}")
        parsed = parse(engine, text)
        out[engine] = parsed.text
    return out


def input_mu(inputs, mu):
    """The scene's friction coefficient with these inputs: the inputs' own (all alike), which a --mu given must
    equal."""
    given = {engine: parse(engine, text).mu for engine, text in inputs.items()}
    values = {m for m in given.values() if m is not None}
    if len(values) > 1:
        each = ", ".join(f"{e} {m:g}" for e, m in given.items())
        raise UserError(f"the engine inputs give different friction coefficients ({each}): compare them one at a time")
    if not values:
        return mu
    value = values.pop()
    if mu is not None and float(mu) != value:
        raise UserError(f"--mu {mu:g} and the engine input's mu {value:g} differ: give one")
    return value

"""YADE 2023.02a's contact inputs as a user writes them (docs/yade-dialect.md#your-own-inputs): a material and its
physics functor with their keyword arguments, `ViscElMat(kn=..., ks=..., cn=..., cs=..., frictionAngle=...)` or
`ViscElMat(tc=..., en=..., et=..., frictionAngle=...)` (Law2_ScGeom_ViscElPhys_Basic), or `FrictMat(young=...,
poisson=..., frictionAngle=...) Ip2_FrictMat_FrictMat_MindlinPhys(en=..., es=...)` (or betan/betas;
Law2_ScGeom_MindlinPhys_Mindlin), composed of neutral sub-models with those numbers. The sphere and its wall (or its
target sphere) share the one material, as in the decks harness writes."""
import math
import re
from dataclasses import dataclass

from ..user_inputs import EngineInput, Flag, refuse
from ...infra.errors import not_modelled
from ...infra.errors import UserError
from ...submodels.normal.given import GivenLinear

MATERIALS = {
    "ViscElMat": ("kn", "ks", "cn", "cs", "tc", "en", "et", "frictionAngle", "mR", "mRtype", "young", "poisson",
                  "density", "lubrication"),
    "FrictMat": ("young", "poisson", "frictionAngle", "density"),
}
FUNCTORS = {
    "Ip2_ViscElMat_ViscElMat_ViscElPhys": (),
    "Ip2_FrictMat_FrictMat_MindlinPhys": ("en", "es", "betan", "betas", "krot", "ktwist", "eta", "gamma"),
    "Law2_ScGeom_ViscElPhys_Basic": (),
    "Law2_ScGeom_MindlinPhys_Mindlin": ("includeAdhesion", "includeMoment", "calcEnergy"),
}
OTHER_CLASSES = ("CohFrictMat", "ViscElCapMat", "LudingMat", "CpmMat", "FrictViscoMat", "JCFpmMat", "ElastMat",
                 "Ip2_CohFrictMat_CohFrictMat_CohFrictPhys", "Ip2_FrictMat_FrictMat_FrictPhys",
                 "Law2_ScGeom_FrictPhys_CundallStrack", "Law2_ScGeom6D_CohFrictPhys_CohesionMoment")
NOT_YET = {          # words that name adhesion or rolling/twisting resistance (a later issue)
    "mR": "ViscElMat's rolling resistance mR", "krot": "Mindlin's rolling stiffness krot",
    "ktwist": "Mindlin's twisting stiffness ktwist", "eta": "Mindlin's rolling limit eta",
    "gamma": "Mindlin's DMT adhesion gamma", "includeAdhesion": "Mindlin's adhesion (includeAdhesion)",
    "includeMoment": "Mindlin's moments (includeMoment)"}
DIRECT, POURNIN = ("kn", "ks", "cn", "cs"), ("tc", "en", "et")
COMMON = {"end": "no-tension", "integrator": "leapfrog", "coulomb": "spring"}
WALL = {"viscel": {**COMMON, "lever": "1"}, "mindlin": {**COMMON, "lever": "1", "slip": "noratch"}}
PAIR = {"viscel": {**COMMON, "geometry": "pair-vector", "lever": "0.5", "torque": "contact-point"},
        "mindlin": {**COMMON, "geometry": "pair-vector", "lever": "0", "slip": "noratch-pair",
                    "torque": "contact-point"}}
CALL = re.compile(r"(\w+)\s*\(([^()]*)\)")
VOCABULARY = "; ".join(f"{name}({', '.join(words)})" for name, words in {**MATERIALS, **FUNCTORS}.items())


@dataclass(frozen=True)
class YadeInput(EngineInput):
    """A parsed YADE input: its law ('viscel' or 'mindlin'), the material's and the functor's keyword values."""
    law: str = "viscel"
    material: tuple = ()
    functor: tuple = ()

    @property
    def values(self):
        return dict(self.material)

    @property
    def form(self):
        """ViscEl's set of constants: 'pournin' (tc, en, et: taken first when all three are given) or 'direct'."""
        v = self.values
        return "pournin" if all(k in v for k in POURNIN) else "direct"

    def law_family(self):
        return "hertz-mindlin" if self.law == "mindlin" else "linear-spring-dashpot"

    def other_engines(self, contact):
        """[(engine, text, release)]: for ViscElMat kn, ks, cn, cs (one material: half of each on the contact), the
        LAMMPS granular words with those numbers, `hooke kn/2 cn/2 damping velocity tangential linear_history ks/2
        cs/cn mu` (velocity damping: a constant c_n; x_gamma_t: c_t/c_n), on 2021.9.29.2, the first release harness
        runs; for FrictMat with Mindlin(en = es), the other engines' Hertz-Mindlin inputs with its numbers."""
        if self.law == "mindlin":
            return self._mindlin_candidates()
        if self.form != "direct":
            return []
        v = self.values
        share = v["cs"] / v["cn"] if v["cn"] else 0.0
        text = (f"hooke {v['kn'] / 2.0!r} {v['cn'] / 2.0!r} damping velocity tangential linear_history "
                f"{v['ks'] / 2.0!r} {share!r} {self.mu!r} limit_damping")
        return [("lammps", text, "2021.9.29.2")]

    def _mindlin_candidates(self):
        """The other engines' Hertz-Mindlin inputs with this material's numbers and its en (engines/material_inputs.py),
        where en and es are one value."""
        from ..material_inputs import hertz_material
        v, f = self.values, dict(self.functor)
        e = f.get("en", f.get("es"))
        if e is None or f.get("es", e) != e:
            return []
        return hertz_material(v["young"], v["poisson"], e, self.mu, skip="yade")

    def flags(self, version=None):
        v, out = {**self.values, **dict(self.functor)}, []
        if "density" in v:
            out.append(Flag("density", f"density {v['density']:g} not used: the sphere's density is the scene's "
                                       f"(--rho)"))
        if self.law == "viscel" and self.form == "pournin":
            ignored = [k for k in DIRECT if k in v]
            if ignored:
                out.append(Flag(",".join(ignored), f"{', '.join(ignored)} not used: YADE takes tc, en, et when all "
                                                   f"three are given"))
            for name in ("en", "et"):
                if v[name] > 1.0:
                    out.append(Flag(name, f"{name} = {v[name]:g} > 1: a negative dashpot that adds energy"))
        elif self.law == "viscel":
            for name in DIRECT:
                if v[name] < 0.0:
                    out.append(Flag(name, f"{name} = {v[name]:g} < 0: " + ("a negative dashpot that adds energy"
                                                                            if name[0] == "c" else
                                                                            "a negative stiffness")))
        else:
            for name in ("en", "es"):
                if name in v and v[name] > 1.0:
                    out.append(Flag(name, f"{name} = {v[name]:g} > 1: outside Thornton's fit (0, 1]"))
            for name in ("betan", "betas"):
                if name in v and v[name] < 0.0:
                    out.append(Flag(name, f"{name} = {v[name]:g} < 0: a negative dashpot that adds energy"))
        return tuple(out)

    def deck_values(self):
        """What the script template takes: the material class with its keyword values (density and frictionAngle
        apart), the friction angle, the physics functor's keyword values and the Law2 functor."""
        v = self.values
        args = [(k, v[k]) for k in (POURNIN if self.form == "pournin" else DIRECT)] if self.law == "viscel" else \
            [(k, v[k]) for k in ("young", "poisson")]
        if self.law == "viscel":
            return dict(material="ViscElMat", material_args=args, friction_angle=v["frictionAngle"],
                        ip2="Ip2_ViscElMat_ViscElMat_ViscElPhys", ip2_args=[],
                        law2="Law2_ScGeom_ViscElPhys_Basic")
        return dict(material="FrictMat", material_args=args, friction_angle=v["frictionAngle"],
                    ip2="Ip2_FrictMat_FrictMat_MindlinPhys", ip2_args=list(self.functor),
                    law2="Law2_ScGeom_MindlinPhys_Mindlin")

    def composition(self, target, version=None):
        """YADE's formulas with these numbers (ViscoelasticPM.cpp, HertzMindlin.cpp at 2023.02a), one material on both
        sides. ViscEl: each constant is taken per side and the contact takes 1/(1/x_1 + 1/x_2), i.e. kn/2, ks/2, cn/2,
        cs/2; with tc, en, et each side's kn = 2 m_R (pi^2 + ln^2 en)/tc^2, cn = -4 m_R ln(en)/tc, ks = 4/7 m_R (pi^2 +
        ln^2 et)/tc^2, cs = -8/7 m_R ln(et)/tc, m_R = m_1 m_2/(m_1 + m_2) with a wall's mass taken as the sphere's
        (m/2). Mindlin: E* = E/(2(1 - nu^2)), G* = E/(4(2 - nu)(1 + nu)), k_n = 2 E* sqrt(R d), k_s = 8 G* sqrt(R d),
        c = 2 beta sqrt(m k), beta from en (Thornton 2013 eqs. B6, B7) or betan."""
        from ...laws.given import given_law
        overrides = (PAIR if target == "sphere" else WALL)[self.law]
        if self.law == "viscel" and self.form == "pournin":
            return self._pournin(target, overrides)
        v = self.values
        if self.law == "viscel":
            kn, ks, cn, cs = (v[k] / 2.0 for k in DIRECT)
            if cn == 0.0 and cs != 0.0:
                not_modelled("ViscElMat cs != 0 with cn = 0 (a constant tangential dashpot without a normal one)")
            return given_law(("linear", kn), (cn,), ("linear", ks), ("share", cs / cn if cn else 0.0), overrides,
                             f"YADE ViscElMat kn {v['kn']:g} ks {v['ks']:g} cn {v['cn']:g} cs {v['cs']:g}")
        young, nu = v["young"], v["poisson"]
        e_star, g_star = young / (2.0 * (1.0 - nu * nu)), young / (4.0 * (2.0 - nu) * (1.0 + nu))
        beta_n, beta_s = self.betas()
        if beta_n == 0.0 and beta_s != 0.0:
            not_modelled("a Mindlin tangential dashpot (es < 1 or betas > 0) without a normal one")
        share = beta_s / beta_n * 2.0 * math.sqrt(g_star / e_star) if beta_n else 0.0
        return given_law(("hertz", e_star), (2.0 * beta_n * math.sqrt(2.0 * e_star), 0.5, 0.25, 0.25),
                         ("mindlin:force", 8.0 * g_star), ("share", share), overrides,
                         f"YADE FrictMat young {young:g} poisson {nu:g} with Mindlin "
                         f"{' '.join(f'{k} {x:g}' for k, x in self.functor) or 'undamped'}")

    def betas(self):
        """(beta_n, beta_s) as Ip2_FrictMat_FrictMat_MindlinPhys sets them: from en/es (either standing for both)
        through Thornton 2013's fit, else betan and betas (betas defaulting to betan), else 0."""
        from ...submodels.calibration import thornton_appendix_b_g
        f = dict(self.functor)
        if "en" in f or "es" in f:
            en, es = f.get("en", f.get("es")), f.get("es", f.get("en"))
            return (0.0 if en == 1.0 else thornton_appendix_b_g(en)), (0.0 if es == 1.0 else thornton_appendix_b_g(es))
        beta_n = f.get("betan", 0.0)
        return beta_n, f.get("betas", beta_n)

    def _pournin(self, target, overrides):
        from ...laws.law import Law, replace_submodels
        from ...submodels.damping.fixed import FixedDashpot
        from ...submodels.tangential.linear import LinearTangential
        from ...submodels.tangential_damping import GivenTangentialDashpot
        v = self.values
        tc, en, et = v["tc"], v["en"], v["et"]
        share = 0.5 if target == "wall" else 1.0            # m_R = m/2 against a wall, m* between two spheres
        per_mass = share * (math.pi ** 2 + math.log(en) ** 2) / tc ** 2
        kt_kn = 2.0 / 7.0 * (math.pi ** 2 + math.log(et) ** 2) / (math.pi ** 2 + math.log(en) ** 2)
        ct_cn = 2.0 / 7.0 * math.log(et) / math.log(en) if en != 1.0 else 0.0
        if en == 1.0 and et != 1.0:
            not_modelled("ViscElMat et < 1 with en = 1 (a tangential dashpot without a normal one)")
        law = Law("input", _MassStiffness(per_mass), FixedDashpot(-2.0 * share * math.log(en) / tc, 1.0), "tension",
                  LinearTangential(repr(kt_kn)), GivenTangentialDashpot(ct_cn, 0.0, 1.0, 0.0),
                  summary=f"YADE ViscElMat tc {tc:g} en {en:g} et {et:g}")
        return replace_submodels(law, overrides)


class _MassStiffness(GivenLinear):
    """k_n = k m: ViscElMat's spring from tc and en, proportional to the contact's mass."""

    def __init__(self, per_mass):
        super().__init__(0.0)
        self.per_mass = per_mass

    def label(self):
        return f"linear(k_n={self.per_mass:.6g} m)"

    def stiffness(self, contact, speed):
        return self.per_mass * contact.mass


def _number(name, value):
    try:
        return float(value)
    except ValueError:
        refuse("yade", f"{name}={value}: ArgumentError, {name} takes a number")


def _keywords(cls, body):
    """{keyword: text} of a call's arguments `k=v, ...`; a positional argument is refused as YADE refuses it."""
    out = {}
    for part in (p.strip() for p in body.split(",") if p.strip()):
        key, sep, value = part.partition("=")
        if not sep:
            refuse("yade", f"{cls}({part}): TypeError, its constructor takes keyword arguments only")
        out[key.strip()] = value.strip().strip("\"'")
    return out


def parse(text, version=None):
    """A YadeInput of `text`: a material call and, for FrictMat, Ip2_FrictMat_FrictMat_MindlinPhys(...)."""
    calls = CALL.findall(text)
    rest = CALL.sub(" ", text).replace("O.materials.append", "").strip(" ;\n[],")
    if rest and not re.fullmatch(r"[\w\s.=\[\],;]*", rest) or not calls:
        refuse("yade", f"cannot read {text!r} as YADE calls (YADE takes {VOCABULARY})")
    material, functor, kind = {}, {}, None
    for cls, body in calls:
        if cls in OTHER_CLASSES:
            not_modelled(f"YADE's {cls} as your own input (a later issue)")
        if cls not in MATERIALS and cls not in FUNCTORS:
            refuse("yade", f"name '{cls}' is not defined (YADE takes {VOCABULARY})")
        words = MATERIALS.get(cls) or FUNCTORS[cls]
        for key, value in _keywords(cls, body).items():
            if key not in words:
                refuse("yade", f"{cls}: No such attribute: {key}. (it takes {', '.join(words) or 'none here'})")
            if key in NOT_YET and value not in ("0", "0.0", "False"):
                not_modelled(f"{NOT_YET[key]} (a later issue)")
            if key in NOT_YET or key in ("calcEnergy", "mRtype"):
                continue
            if key == "lubrication":
                if value == "True":
                    not_modelled("ViscElMat's lubrication (a later issue)")
                continue
            (material if cls in MATERIALS else functor)[key] = _number(key, value)
        if cls in MATERIALS:
            if kind is not None:
                raise UserError("yade input: give one material (the sphere and its wall share it)")
            kind = cls
    if kind is None:
        refuse("yade", f"no material in {text!r} (YADE takes {VOCABULARY})")
    material.setdefault("frictionAngle", 0.5)                    # FrictMat's default, 0.5 rad
    law = "viscel" if kind == "ViscElMat" else "mindlin"
    names = {c for c, _ in calls}
    if law == "mindlin" and "Ip2_FrictMat_FrictMat_MindlinPhys" not in names:
        not_modelled("FrictMat without Ip2_FrictMat_FrictMat_MindlinPhys (CundallStrack; run it with "
                     "--engine-option yade:linear=cundall-strack)")
    if law == "viscel" and names & {"Ip2_FrictMat_FrictMat_MindlinPhys", "Law2_ScGeom_MindlinPhys_Mindlin"} or \
            law == "mindlin" and names & {"Ip2_ViscElMat_ViscElMat_ViscElPhys", "Law2_ScGeom_ViscElPhys_Basic"}:
        refuse("yade", "InteractionLoop: None of given Law2 functors can handle the interaction of these "
                       "material and functors")
    if law == "viscel":
        _check_viscel(material)
    else:
        _check_mindlin(material, functor)
    if material["frictionAngle"] < 0.0:
        raise UserError("yade input: frictionAngle must be >= 0")
    mu = math.tan(material["frictionAngle"])
    words = [f"{cls}({body.strip()})" for cls, body in calls]
    return YadeInput("yade", " ".join(words), tuple(words), mu=mu, law=law, material=tuple(material.items()),
                     functor=tuple(functor.items()))


def _check_viscel(v):
    """ViscElMat's sets of constants, refused where Ip2_ViscElMat_ViscElMat_ViscElPhys throws."""
    if all(k in v for k in POURNIN):
        if v["tc"] <= 0.0 or v["en"] <= 0.0 or v["et"] <= 0.0:
            raise UserError("yade input: tc, en and et must be > 0 (YADE takes their logarithm and 1/tc)")
        return
    if all(k in v for k in DIRECT):
        return
    if "en" in v or ("young" in v and "cn" in v and "cs" in v):
        not_modelled("ViscElMat from young, poisson and en or cn, cs (a later issue)")
    refuse("yade", "Inconsistent material constants for ViscElMat's, please check input (give kn, ks, cn, cs or "
                   "tc, en, et)")


def _check_mindlin(v, f):
    if "en" in f and "betan" in f:
        refuse("yade", "Ip2_FrictMat_FrictMat_MindlinPhys: only one of en, betan can be specified.")
    if "es" in f and "betas" in f:
        refuse("yade", "Ip2_FrictMat_FrictMat_MindlinPhys: only one of es, betas can be specified.")
    v.setdefault("young", 1e9)
    v.setdefault("poisson", 0.25)
    if v["young"] <= 0.0 or not -1.0 < v["poisson"] < 1.0:
        raise UserError("yade input: young must be > 0 and -1 < poisson < 1 for Hertz-Mindlin")
    for name in ("en", "es"):
        if name in f and not f[name] > 0.0:
            raise UserError(f"yade input: {name} must be > 0 (Thornton's fit is for 0 < e <= 1)")


def contact_text(script, path):
    """The material and functor calls of a YADE script (the calls named in MATERIALS and FUNCTORS, and those
    refused as not yet modelled)."""
    known = set(MATERIALS) | set(FUNCTORS) | set(OTHER_CLASSES)
    code = "\n".join(line.split("#", 1)[0] for line in script.splitlines())
    calls = [f"{cls}({' '.join(body.split())})" for cls, body in CALL.findall(code) if cls in known]
    if not calls:
        raise UserError(f"--engine-input @{path}: no YADE material or Ip2/Law2 functor call in it")
    return " ".join(dict.fromkeys(calls))

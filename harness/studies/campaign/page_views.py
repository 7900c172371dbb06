"""The named views of `harness query` that the campaign page's tables are drawn from: `agreement` (per engine, law
and scene, the worst relative difference of the rebound velocities from its formulas at equal dt, as
analyses.agreement computes it for one comparison) and `deviation_map` (per engine, law, e_n and impact angle, the
worst |engine - paper law| of each metric over the rest of the matrix), with the SQL that prints each of the page's
tables from them."""
from ...analyses.agreement import AGREEMENT_TOLERANCE
from ...infra.releases import release_text

AGREEMENT, MAP = "agreement", "deviation_map"
GROUP = ("model", "material", "wall", "target", "radius", "E", "nu", "rho", "mu", "omega0", "steps_per_contact",
         "speed")
PAIRED = GROUP + ("e_n_target", "theta_deg", "v_n0", "v_t0")


def _relative(column, scale):
    """|a - b| / max(|b|, 1e-9 scale) (analyses.agreement.relative_difference) of the pair's `column`."""
    return f"abs({column} - {column}_ref) / greatest(abs({column}_ref), 1e-9 * {scale})"


_PAIRS = (   # each engine's row in its own formulas beside the reference's in the same formulas on the same impact
    "SELECT e.engine, " + ", ".join(f"e.{c}" for c in PAIRED) + ", e.v_n1, e.v_t1, e.omega1, r.v_n1 AS v_n1_ref, "
    "r.v_t1 AS v_t1_ref, r.omega1 AS omega1_ref, max(abs(e.v_n0)) OVER scene + max(abs(e.v_t0)) OVER scene AS scale "
    "FROM results e JOIN results r ON " + " AND ".join(f"e.{c} IS NOT DISTINCT FROM r.{c}" for c in PAIRED)
    + " AND r.dialect = e.dialect WHERE e.engine <> 'reference' AND e.dialect = e.engine AND e.status = 'ok' "
    "AND r.engine = 'reference' AND r.status = 'ok' WINDOW scene AS (PARTITION BY e.engine, "
    + ", ".join(f"e.{c}" for c in GROUP) + ")")
_DIFFERENCES = (f"SELECT engine, {', '.join(GROUP)}, greatest({_relative('v_n1', 'scale')}, "
                f"{_relative('v_t1', 'scale')}, {_relative('omega1', 'scale / radius')}) AS diff FROM ({_PAIRS})")
AGREEMENT_SQL = (f"CREATE VIEW {AGREEMENT} AS SELECT engine, {', '.join(GROUP)}, max(diff) AS worst, "
                 f"max(diff) <= {AGREEMENT_TOLERANCE!r} AS agrees, count(*) AS impacts FROM ({_DIFFERENCES}) "
                 "GROUP BY ALL")
MAP_SQL = (f"CREATE VIEW {MAP} AS SELECT engine, model, e_n_target, theta_deg, max(d_e_n) AS worst_d_e_n, "
           "max(d_e_t) AS worst_d_e_t, max(d_omega_star) AS worst_d_omega_star, count(*) AS impacts FROM deviations "
           "GROUP BY ALL")


def register_release_order(db):
    """The SQL function release_order(engine): text that sorts the builds of an engine in release order
    (releases.release_text), so that every table of the page lists them as every other view does."""
    db.create_function("release_order", release_text, ["VARCHAR"], "VARCHAR", side_effects=False)


def create(db):
    """Add the views `agreement` and `deviation_map` to a connection that has `results` and `deviations`."""
    db.execute(AGREEMENT_SQL)
    db.execute(MAP_SQL)


def agreement_sql():
    """The page's agreement table: every row of the view, in order."""
    return (f"SELECT engine, {', '.join(GROUP)}, worst, agrees FROM {AGREEMENT} ORDER BY release_order(engine), "
            + ", ".join(GROUP))


def failures_sql():
    """The page's failed tasks: each engine, law and e_n whose run failed, with its one-line reason."""
    return ("SELECT DISTINCT engine, model, e_n_target, message FROM results WHERE status = 'failed' "
            "ORDER BY release_order(engine), model, e_n_target")


def quoted(word):
    return "'" + str(word).replace("'", "''") + "'"


def map_sql(engine, law, angles, metric="e_t"):
    """One map of the page: e_n down, the impact angles across, the worst |metric(engine) - metric(paper law)|."""
    within = f"engine = {quoted(engine)} AND model = {quoted(law)}"
    return (f"PIVOT (SELECT e_n_target, theta_deg, worst_d_{metric} FROM {MAP} WHERE {within}) ON theta_deg IN ("
            + ", ".join(f"{a!r}" for a in angles) + f") USING max(worst_d_{metric}) ORDER BY e_n_target")


def maps_sql():
    """Which maps there are, and their angles: each engine and law with the impact angles it ran."""
    return (f"SELECT engine, model, list(DISTINCT theta_deg ORDER BY theta_deg) AS angles FROM {MAP} "
            "GROUP BY engine, model ORDER BY release_order(engine), model")

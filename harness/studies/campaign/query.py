"""A read-only SQL query over a campaign store (`harness query`). DuckDB gets the store's fragments as Arrow datasets
opened here by path (no file name ever becomes SQL text), each task's rows once, and runs with access to files,
extensions and Python objects switched off and its configuration locked from the start; only one SELECT (WITH,
DESCRIBE, SHOW, SUMMARIZE, VALUES) is run, within stated limits of memory and time, and its result is read in
batches only while it stays small enough to print."""
import contextlib
import os
import resource
import threading

import pyarrow as pa
import pyarrow.dataset as ds
import pyarrow.fs as pafs
import pyarrow.parquet as pq

from ...infra.errors import UserError
from . import page_views
from .fragments import KEY
from .store import SCENE
from .limits import MAX_QUERY_BYTES, MAX_QUERY_S, MAX_RESULT_BYTES, MAX_ROWS, QUERY_GROWTH_MB, QUERY_MEMORY_MB

VIEW = "results"
DEVIATIONS = "deviations"
SAME_SCENE = ("model", "e_n_target", "theta_deg", "mu", "radius", "E", "nu", "rho", "omega0", "steps_per_contact",
              "v_n0", "v_t0", "material", "wall", "target", "speed")
DEVIATION_SQL = (   # each engine's own-formula row against the paper law's on the same impact
    f"CREATE VIEW {DEVIATIONS} AS SELECT e.engine, " + ", ".join(f"e.{c}" for c in SAME_SCENE) + ", "
    "abs(e.e_n - p.e_n) AS d_e_n, abs(e.e_t - p.e_t) AS d_e_t, abs(e.omega_star - p.omega_star) AS d_omega_star "
    f"FROM {VIEW} e JOIN {VIEW} p ON " + " AND ".join(f"e.{c} IS NOT DISTINCT FROM p.{c}" for c in SAME_SCENE)
    + " WHERE p.engine = 'reference' AND p.dialect = 'paper' AND p.status = 'ok' AND e.engine <> 'reference' "
    "AND e.dialect = e.engine AND e.status = 'ok'")
LOCKED = {"enable_external_access": False, "autoinstall_known_extensions": False,
          "autoload_known_extensions": False, "python_enable_replacements": False,
          "memory_limit": f"{QUERY_MEMORY_MB}MB", "threads": 1}
BATCH = 4096                      # rows read from DuckDB at a time


def statement(sql):
    """The one SELECT statement of `sql`; UserError for none, several, or any other kind."""
    import duckdb
    if not isinstance(sql, str):
        raise UserError(f"the query must be text, got {type(sql).__name__}")
    if len(sql.encode("utf-8", "replace")) > MAX_QUERY_BYTES:
        raise UserError(f"the query is longer than {MAX_QUERY_BYTES} bytes")
    try:
        sql.encode("utf-8")
    except UnicodeEncodeError as exc:       # bytes of the command line that are not UTF-8
        raise UserError(f"the query is not UTF-8 text (character {exc.start + 1})") from None
    try:
        found = duckdb.extract_statements(sql)
    except duckdb.Error as exc:
        raise UserError(f"query failed: {first_line(exc)}") from None
    if not found:
        raise UserError("the query is empty: give one SELECT over the view results")
    if len(found) > 1:
        raise UserError(f"the query holds {len(found)} statements; give one SELECT over the view results")
    if found[0].type != duckdb.StatementType.SELECT:
        kind = found[0].type.name.replace("_", " ")
        raise UserError(f"harness query only reads: SELECT, WITH, DESCRIBE, SHOW or SUMMARIZE, not {kind}")
    return found[0].query


def first_line(exc):
    return (str(exc).strip().splitlines() or [type(exc).__name__])[0][:300]


def connection(store):
    """An in-memory DuckDB connection, locked down, whose view `results` is the store with each task once, whose
    view `deviations` pairs each engine's row (its own formulas) with the paper law's on the same impact, and with
    the views the campaign page draws from (page_views)."""
    import duckdb
    copies = {name: keys for name, keys in store.copies().items() if keys}
    if not copies:
        raise UserError(f"store {store.path} holds no campaign results (no *.parquet fragments)")
    paths = {name: os.path.abspath(os.path.join(store.path, name)) for name in copies}
    local = pafs.LocalFileSystem()
    try:
        schema = pa.unify_schemas([pq.read_schema(paths[name], filesystem=local) for name in copies])
    except (OSError, pa.ArrowException) as exc:
        raise UserError(f"store {store.path}: its fragments' columns do not agree ({first_line(exc)})") from None
    db = duckdb.connect(":memory:", config=LOCKED)
    db.execute("SET enable_progress_bar = false")     # not settable at connect; nothing else runs before the lock
    page_views.register_release_order(db)
    db.execute("SET lock_configuration = true")
    whole = [paths[name] for name, keys in copies.items() if keys == store.held[name]]
    parts = []
    if whole:
        db.register("store_fragments", ds.dataset(whole, schema=schema, format="parquet", filesystem=local))
        parts.append("SELECT * FROM store_fragments")
    for i, name in enumerate(n for n, keys in copies.items() if keys != store.held[n]):
        db.register(f"store_partial_{i}", ds.dataset([paths[name]], schema=schema, format="parquet",
                                                     filesystem=local))
        db.register(f"store_keys_{i}", pa.table({KEY: sorted(copies[name])}))
        parts.append(f"SELECT * FROM store_partial_{i} WHERE {KEY} IN (SELECT {KEY} FROM store_keys_{i})")
    missing = "".join(f", NULL::{'DOUBLE' if c == 'speed' else 'VARCHAR'} AS {c}" for c in SCENE
                      if c not in schema.names)          # a store written before its rows held their scene's columns
    db.execute(f"CREATE VIEW {VIEW} AS SELECT *{missing} FROM (" + " UNION ALL BY NAME ".join(parts) + ")")
    db.execute(DEVIATION_SQL)
    page_views.create(db)
    return db


def query(store, sql):
    """The result of one read-only SELECT over the view `results`, within the limits (UserError beyond them)."""
    import duckdb
    text = statement(sql)
    db = connection(store)
    timer = threading.Timer(MAX_QUERY_S, db.interrupt)
    timer.daemon = True
    timer.start()
    try:
        with growth_within(QUERY_GROWTH_MB << 20):
            relation = db.sql(text)
            table = bounded(getattr(relation, "to_arrow_reader", None) or relation.fetch_arrow_reader)
            return table.to_pandas()
    except MemoryError:
        raise UserError(f"the query needs more than {QUERY_MEMORY_MB} MB of memory: narrow it") from None
    except (duckdb.Error, pa.ArrowException, OSError) as exc:       # a batch's error comes through Arrow
        raise refusal(exc) from None
    finally:
        timer.cancel()
        db.close()


@contextlib.contextmanager
def growth_within(extra):
    """While the block runs, this process's address space may grow by `extra` bytes at most (an allocation beyond
    fails, which DuckDB reports as out of memory)."""
    soft, hard = resource.getrlimit(resource.RLIMIT_AS)
    with open("/proc/self/statm") as statm:
        size = int(statm.read().split()[0]) * resource.getpagesize()
    limit = size + extra if hard == resource.RLIM_INFINITY else min(size + extra, hard)
    resource.setrlimit(resource.RLIMIT_AS, (limit if soft == resource.RLIM_INFINITY else min(limit, soft), hard))
    try:
        yield
    finally:
        resource.setrlimit(resource.RLIMIT_AS, (soft, hard))


TABLES = (f"the store is the view {VIEW} (one row per impact: the columns of results.csv, docs/results.md, and the "
          f"task's; `DESCRIBE {VIEW}` lists them), beside the views {DEVIATIONS}, {page_views.AGREEMENT} and "
          f"{page_views.MAP}")


def refusal(exc):
    """The one line for a query DuckDB stopped: over its time or memory limit, or failing; a table or column that
    does not exist is told where the store's rows are."""
    import duckdb
    text = first_line(exc)
    if isinstance(exc, duckdb.InterruptException) or text.startswith("INTERRUPT"):
        return UserError(f"the query ran longer than {MAX_QUERY_S:g} s and was stopped: narrow it")
    if isinstance(exc, duckdb.OutOfMemoryException) or text.startswith("Out of Memory"):
        return UserError(f"the query needs more than {QUERY_MEMORY_MB} MB of memory: narrow it")
    if isinstance(exc, duckdb.CatalogException):
        return UserError(f"query failed: {text.rstrip('!')}: {TABLES}")
    if isinstance(exc, duckdb.BinderException) and "not found" in text:
        lines = str(exc).strip().splitlines()
        candidates = next((line.strip() for line in lines[1:] if line.startswith("Candidate")), "")
        return UserError(f"query failed: {text.rstrip('!')}" + (f" ({candidates[:200]})" if candidates else "")
                         + f": {TABLES}")
    return UserError(f"query failed: {text}")


def bounded(open_reader):
    """The batches of open_reader(BATCH) as one table, read only while within MAX_ROWS rows and MAX_RESULT_BYTES."""
    reader = open_reader(BATCH)
    batches, rows, size = [], 0, 0
    for batch in reader:
        rows, size = rows + batch.num_rows, size + batch.nbytes
        if rows > MAX_ROWS:
            raise UserError(f"the result has more than {MAX_ROWS} rows, too many to print: narrow the query "
                            "(WHERE, GROUP BY, LIMIT)")
        if size > MAX_RESULT_BYTES:
            raise UserError(f"the result holds more than {MAX_RESULT_BYTES >> 20} MiB, too much to print: narrow "
                            "the query")
        batches.append(batch)
    return pa.Table.from_batches(batches, schema=reader.schema)

"""`harness query STORE "SQL"`: SQL over a campaign store with DuckDB; the store is the view `results`."""
from ..errors import UserError
from .options import EXIT_OK


def add(sub, describe):
    p = describe(sub, "query", "SQL over a campaign store (DuckDB; the store is the view `results`)",
                 "harness query campaign-store \"SELECT engine, max(abs(e_t)) FROM results GROUP BY engine\"")
    p.add_argument("store", metavar="STORE")
    p.add_argument("sql", metavar="SQL")
    p.add_argument("--csv", action="store_true", help="print CSV instead of a table")
    p.set_defaults(func=main)


def main(args):
    import glob
    import os

    import duckdb
    files = sorted(glob.glob(os.path.join(args.store, "*.parquet")))
    if not files:
        raise UserError(f"{args.store} holds no campaign results (no *.parquet files)")
    connection = duckdb.connect()
    connection.execute(f"CREATE VIEW results AS SELECT * FROM read_parquet({files!r}, union_by_name = true)")
    try:
        frame = connection.execute(args.sql).df()
    except duckdb.Error as exc:
        raise UserError(f"query failed: {str(exc).splitlines()[0]}") from None
    print(frame.to_csv(index=False) if args.csv else frame.to_string(index=False))
    return EXIT_OK

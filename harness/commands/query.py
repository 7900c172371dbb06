"""`harness query STORE "SQL"`: one read-only SELECT over a campaign store with DuckDB; the store is the view
`results`, each task's rows once (harness.studies.campaign.query says what a query may and may not do)."""
import pandas as pd

from ..studies.campaign.limits import MAX_CELL_CHARS
from ..studies.campaign.query import query
from ..studies.campaign.store import Store
from ..infra.errors import UserError
from .options import EXIT_OK


def main(args):
    frame = query(Store(args.store, create=False, drop_damaged=args.drop_damaged), args.sql)
    widest = max((int(frame.iloc[:, i].astype(str).str.len().fillna(0).max()) for i in range(frame.shape[1])
                  if len(frame) and not pd.api.types.is_numeric_dtype(frame.iloc[:, i])), default=0)
    if widest > MAX_CELL_CHARS:
        raise UserError(f"a value of the result has {widest} characters, more than {MAX_CELL_CHARS} to print: "
                        "narrow the query")
    text = frame.to_csv(index=False) if args.csv else frame.to_string(index=False)
    print(text, end="" if text.endswith("\n") else "\n")
    return EXIT_OK

"""What harness' threads use, loaded by the main thread before it starts them: an import made on a thread waits on
import locks that another thread may hold (pandas loading pyarrow for a string column while another thread imports),
and a main thread caught in such a wait never handles SIGTERM again."""
import codecs

import pandas as pd

from ..engines import batches  # noqa: F401  (an engine's run imports it when it starts: on its thread)


def import_what_threads_use():
    """Load here what threads would otherwise import on first use: pandas' pyarrow layer (a string column loads it),
    the engines' batches (imported above) and the unicode_escape codec (jinja's lexer looks it up when it compiles an
    engine's template)."""
    frame = pd.DataFrame({"text": ["x"], "number": [1.0]})
    pd.concat([frame, frame], ignore_index=True).to_csv()
    codecs.lookup("unicode_escape")

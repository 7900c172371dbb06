"""`harness report DIR`: rebuild DIR/report.html from the files of a compare or cost directory (DIR/scene.html from
a scene run's), simulating nothing."""
import os

from ..runs.outputs import REPORT
from ..studies.scene_files import DESCRIPTION, load_scene
from ..views.figure_files import FIGURES
from ..views.html import rebuild
from .options import EXIT_OK, check_entries


def main(args):
    if os.path.isfile(os.path.join(args.directory, DESCRIPTION)):
        from ..views.scene_html import PAGE, write_scene_report
        check_entries(args.directory, (PAGE,), (FIGURES,))
        print(f"wrote {write_scene_report(args.directory, *load_scene(args.directory))}")
        return EXIT_OK
    check_entries(args.directory, (REPORT,), (FIGURES,))
    print(f"wrote {rebuild(args.directory)}")
    return EXIT_OK

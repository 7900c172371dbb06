"""Views of the data: the terminal, the HTML report and its figures."""

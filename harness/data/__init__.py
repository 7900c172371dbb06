"""The tables harness writes and reads (results, run.json and cost.json records, column descriptions), the paper's
digitised curves, and the package data: report templates and the committed baseline."""

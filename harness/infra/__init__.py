"""What every floor uses: errors a user can cause, whole-or-nothing files, the lock, reading user files, where programs
are, the compile cache, rendering, wording, releases, version and citation (docs/design.md: the package, floor by
floor)."""

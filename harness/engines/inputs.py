"""Which engines read their own inputs (--engine-input ENGINE=TEXT): each engine's vocabulary is one module beside its
dialect, registered here by one line (harness/engines/user_inputs.py reads it)."""
VOCABULARIES = {
    "lammps": ".lammps.inputs",
    "liggghts": ".liggghts.inputs",
    "yade": ".yade.inputs",
    "kratos": ".kratos.inputs",
}

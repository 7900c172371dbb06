"""Integrators: how a contact is stepped in time. EXPLICIT: the dashpots are explicit (the stability limit is the
damped oscillator's); EVENTS: the release and each change of regime are located inside their step (the contact
ends inside it, not at it); ADAPTIVE: the adaptive integrator of the converged mode is its h -> 0 limit."""

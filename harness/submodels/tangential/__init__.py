"""Tangential sub-models: the spring (or spring-less friction) capped by Coulomb |F_t| <= mu F_n."""

"""Touch rules: at which overlap a sphere is in contact (`contact(alpha)`), so whether one placed at gap 0 feels a
force before its first step."""

"""Geometry 'stand-in-sphere': a huge fixed sphere plays the wall."""
NAME = "stand-in-sphere"
SUMMARY = ("a fixed sphere of the normal model's stand-in radius plays the wall: overlap from the centres, the "
           "normal turning, the shear vector turned with it, forces at the middle of the overlap")
SLOTS = ("radius",)


def parameters(law, scene):
    """The fixed sphere's radius, the normal model's."""
    return {"radius": law.normal.stand_in_radius(scene.contact)}

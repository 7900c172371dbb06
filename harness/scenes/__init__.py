"""What is simulated: the scene, its materials and bodies, and the rebound kinematics of an impact."""

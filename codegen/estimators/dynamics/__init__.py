"""Reduced dynamic EKFs (seeds 000 and 003): multibody models whose state holds coordinates,
velocities and the unknown efforts (joint torques, ground reactions) as a random walk."""

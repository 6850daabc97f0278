"""Real to sim: reconstruct scenes and assets from camera and LIDAR captures into splats and collision meshes."""

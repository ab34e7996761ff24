/**
 * The patch test of brickwork_patch.cc (distorted meshes, uniform
 * compression, series formula and linear displacement field to 1e-8) on
 * two MPI ranks: the METIS partition cuts the distorted bricks and joints.
 * (A separate test so that ctest -j does not build one executable twice.)
 */
#include "brickwork_patch.cc"

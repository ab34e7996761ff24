/**
 * @file
 * The complete types of the parts of the model that the public ModelView
 * (include/masonry/brickwork/view.h) only declares: for the built-in
 * postprocessors and the step loop.
 */
#ifndef masonry_brickwork_model_view_h
#define masonry_brickwork_model_view_h

#include <masonry/brickwork/brick_material.h>
#include <masonry/brickwork/interface_law.h>
#include <masonry/brickwork/view.h>

#include "interface_element.h"
#include "joints.h"
#include "mesh.h"
#include "point_states.h"
#include "specimen.h"
#include "step_control.h"
#include "system.h"

#endif

/**
 * @file
 * The complete types of the parts of the model that the public ModelView
 * (include/masonry/brickwork/view.h) only declares: for the view's own
 * functions (view.cc), the model's report (report.cc) and the step loop.
 * The registered outputs do not include it (tests may).
 */
#ifndef masonry_brickwork_model_view_h
#define masonry_brickwork_model_view_h

#include <masonry/brickwork/brick_material.h>
#include <masonry/brickwork/interface_law.h>
#include <masonry/brickwork/view.h>

#include "../assembly/interface_element.h"
#include "../assembly/point_states.h"
#include "../assembly/system.h"
#include "../specimen/joints.h"
#include "../specimen/mesh.h"
#include "../specimen/specimen.h"
#include "../wallette.h"

#endif

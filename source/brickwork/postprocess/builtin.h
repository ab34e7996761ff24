/**
 * @file
 * What the built-in wallette postprocessors include: the public base class
 * and the complete types of the model's parts.
 */
#ifndef masonry_brickwork_postprocess_builtin_h
#define masonry_brickwork_postprocess_builtin_h

#include <masonry/brickwork/postprocessor.h>

#include "view.h"

namespace masonry
{
  namespace brickwork
  {
    namespace postprocess
    {
      using model::System;
    } // namespace postprocess
  }   // namespace brickwork
} // namespace masonry

#endif

/**
 * @file
 * OneThread for the model's own files (the class is public:
 * include/masonry/brickwork/one_thread.h).
 */
#ifndef masonry_brickwork_model_one_thread_h
#define masonry_brickwork_model_one_thread_h

#include <masonry/brickwork/one_thread.h>

#endif

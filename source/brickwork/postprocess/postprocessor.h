/**
 * @file
 * The outputs of a wallette run as postprocessors (ASPECT's model): each
 * reads the model through a read-only view at fixed points of the step loop
 * and writes its files; what it must remember across a restart it saves
 * into the checkpoint.
 */
#ifndef masonry_brickwork_postprocess_postprocessor_h
#define masonry_brickwork_postprocess_postprocessor_h

#include <masonry/core/json.h>

#include <memory>
#include <string>
#include <vector>

#include "../model/view.h"

namespace masonry
{
  namespace brickwork
  {
    namespace postprocess
    {
      using model::ModelView;
      using model::System;

      /** Base class of the wallette postprocessors. */
      class Postprocessor
      {
      public:
        virtual ~Postprocessor() = default;

        /** Before the first step of a run that starts from zero (the
         * curve holds the initial state). */
        virtual void
        start(const ModelView &view);

        /** After a run has been resumed from a checkpoint (the curve holds
         * the steps up to it). */
        virtual void
        resume(const ModelView &view);

        /** After every converged step (the curve's last point). */
        virtual void
        step(const ModelView &view);

        /** At the output steps (`Output interval', the initial and the last
         * state): @p step and @p time (the strain) name the output. */
        virtual void
        output(const ModelView   &view,
               const unsigned int step,
               const double       time);

        /** At the end of the run: files of the whole run and entries of
         * summary.json. */
        virtual void
        finish(const ModelView &view, Json &summary);

        /** What to keep across a restart (written into the checkpoint). */
        virtual std::string
        save() const;

        /** Restore what save() returned. */
        virtual void
        load(const std::string &data);
      };

      /**
       * The postprocessors of @p settings, in the order they run: curve
       * tables, fields, joint fields, curve plot, CalculiX export.
       */
      std::vector<std::unique_ptr<Postprocessor>>
      create_postprocessors(const WalletteSettings &settings);
    } // namespace postprocess
  }   // namespace brickwork
} // namespace masonry

#endif

/**
 * @file
 * The outputs of a wallette run as postprocessors (ASPECT's model): each
 * reads the model through a read-only view (ModelView) at fixed points of
 * the step loop and writes its files; what it must remember across a
 * restart it saves into the checkpoint. A postprocessor can live in a shared
 * library loaded with `Additional shared libraries' (see
 * contrib/examples/wallette_postprocessor).
 */
#ifndef masonry_brickwork_postprocessor_h
#define masonry_brickwork_postprocessor_h

#include <masonry/brickwork/view.h>
#include <masonry/core/json.h>
#include <masonry/core/plugins.h>

#include <string>

namespace masonry
{
  namespace brickwork
  {
    /** Output files (`Output interval', `Write VTU', `Output format',
     * `Write plot', `Write CalculiX input'). */
    struct OutputSettings
    {
      /** Write VTU every this many converged steps (0: only the last). */
      unsigned int vtu_interval = 10;
      /** Write VTU/PVD at all. */
      bool write_vtu = true;
      /** Brick fields as HDF5 + XDMF (solution.xdmf, solution_NNNN.h5)
       * instead of VTU/PVTU + PVD. */
      bool hdf5 = false;
      /** Render curve.png with matplotlib. */
      bool write_plot = true;
      /**
       * Write the mesh and the final platen displacement as a CalculiX
       * input (calculix.inp) and the computed nodal displacements
       * (nodal_displacements.csv) in the same numbering.
       */
      bool write_calculix = false;

      /** Declare the entries in the present subsection (`subsection
       * Wallette'). */
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      /** Read them. */
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    namespace postprocess
    {
      /**
       * Base class of the wallette postprocessors, a plugin family with a
       * list (`subsection Postprocess / subsection Wallette / set List of
       * postprocessors`); the default list gives the outputs of earlier
       * versions. A new output is one file: a class derived from this with
       * a static declare_parameters() and one
       * MASONRY_REGISTER_WALLETTE_POSTPROCESSOR line.
       */
      class Postprocessor : public plugins::InterfaceBase
      {
      public:
        /** Parameters live in `subsection Postprocess/Wallette`. */
        static constexpr const char *registry_section = "Postprocess/Wallette";
        /** The selection entry: a list. */
        static constexpr const char *registry_entry = "List of postprocessors";
        /** Any number of postprocessors run at once. */
        static constexpr bool multiple_selection = true;
        /** Today's outputs: curve tables, fields, joint fields, curve plot. */
        static const char *
        default_plugin();
        /** Help text of the selection entry. */
        static std::string
        selection_documentation();


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

        /** After every postprocessor's finish() and the run's own entries of
         * summary.json (status, steps, solver counters): for an output that
         * reports the whole run from its files and @p summary (the report
         * page). Nothing by default. */
        virtual void
        after_summary(const ModelView &view, const Json &summary);

        /** What to keep across a restart (written into the checkpoint). */
        virtual std::string
        save() const;

        /** Restore what save() returned. */
        virtual void
        load(const std::string &data);
      };

    } // namespace postprocess
  }   // namespace brickwork
} // namespace masonry

/** Register a wallette postprocessor (one line in its .cc file). */
#define MASONRY_REGISTER_WALLETTE_POSTPROCESSOR(classname, name, description) \
  MASONRY_REGISTER_PLUGIN(masonry::brickwork::postprocess::Postprocessor,     \
                          classname,                                          \
                          name,                                               \
                          description)

#endif

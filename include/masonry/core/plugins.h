/**
 * @file
 * The plugin registry, in the style of ASPECT's `plugins.h`.
 *
 * Every pluggable subsystem (analysis, geometry model, LP solver, ...) has an
 * abstract interface class that names where its parameters live:
 *
 * @code
 * class Interface
 * {
 * public:
 *   static constexpr const char *registry_section = "Geometry model";
 *   static constexpr const char *registry_entry   = "Model name";
 *   virtual ~Interface() = default;
 *   static const char *default_plugin();             // the default selection
 *   static std::string selection_documentation();    // help text of the entry
 *   static void declare_common_parameters(dealii::ParameterHandler &prm);
 *   virtual void parse_common_parameters(dealii::ParameterHandler &prm);
 *   virtual void parse_parameters(dealii::ParameterHandler &prm);
 *   ...
 * };
 * @endcode
 *
 * A plugin is a class derived from the interface with a static
 * `declare_parameters(ParameterHandler &)` and a default constructor; one
 * line registers it:
 *
 * @code
 * MASONRY_REGISTER_PLUGIN(masonry::geometry::Interface, BarrelVault,
 *                         "barrel vault", "A circular or pointed barrel ...")
 * @endcode
 *
 * The registry then declares, inside `subsection <registry_section>`, the
 * selection entry `<registry_entry>` (pattern and help text generated from the
 * registered names), the entries shared by all plugins of the subsystem
 * (declare_common_parameters(), read by parse_common_parameters()) and one
 * subsection per plugin, named after the plugin with
 * its first letter capitalised (`subsection Barrel vault`), in which the
 * plugin declares its own entries. Only the selected plugin is created and
 * parsed, so a run pays nothing for the plugins it does not use.
 */
#ifndef masonry_core_plugins_h
#define masonry_core_plugins_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace masonry
{
  namespace plugins
  {
    /**
     * Name of the subsection that holds the parameters of the plugin called
     * @p plugin_name: the name with its first letter in upper case.
     */
    std::string
    section_name(const std::string &plugin_name);

    /**
     * Enter the (possibly nested, '/'-separated, possibly empty) subsection
     * @p path. Returns the number of levels entered, to be passed to
     * leave_path().
     */
    unsigned int
    enter_path(dealii::ParameterHandler &prm, const std::string &path);

    /** Leave @p n_levels subsections. */
    void
    leave_path(dealii::ParameterHandler &prm, const unsigned int n_levels);

    /**
     * RAII record of the subsection whose entries are being parsed, so that
     * masonry::ExcParameter can name the full path and the input line of an
     * entry with an invalid value.
     */
    class ParsePathScope
    {
    public:
      explicit ParsePathScope(const std::string &path);
      ~ParsePathScope();
    };

    /** The path most recently pushed by a ParsePathScope ("" at top level). */
    std::string
    current_parse_path();

    /**
     * A subsystem known to the registry: every subsystem with at least one
     * registered plugin appears here, so that the driver can declare all
     * parameters of all plugins (for `--print-parameters`).
     */
    struct Subsystem
    {
      std::string                                     section;
      std::string                                     entry;
      std::function<void(dealii::ParameterHandler &)> declare;
    };

    /** Register a subsystem (called once per interface class). */
    void
    add_subsystem(const Subsystem &subsystem);

    /** All subsystems, sorted by section name (deterministic output). */
    std::vector<Subsystem>
    subsystems();

    /**
     * The list of plugins implementing @p Interface.
     */
    template <class Interface>
    class Registry
    {
    public:
      using Declare = void (*)(dealii::ParameterHandler &);
      using Factory = std::unique_ptr<Interface> (*)();

      /** One registered plugin. */
      struct Entry
      {
        std::string name;
        std::string description;
        Declare     declare;
        Factory     create;
      };

      /**
       * Add a plugin. Called by MASONRY_REGISTER_PLUGIN during static
       * initialisation of the library or of an additional shared library.
       */
      static bool
      add(const std::string &name,
          const std::string &description,
          Declare            declare,
          Factory            create)
      {
        auto &list = storage();
        if (list.empty())
          add_subsystem({Interface::registry_section,
                         Interface::registry_entry,
                         &Registry::declare_parameters});
        for (const auto &e : list)
          AssertThrow(e.name != name,
                      dealii::ExcMessage("Two plugins register the name '" +
                                         name + "' for '" +
                                         Interface::registry_entry + "'."));
        list.push_back({name, description, declare, create});
        std::sort(list.begin(), list.end(), [](const Entry &a, const Entry &b) {
          return a.name < b.name;
        });
        return true;
      }

      /** The registered plugins, sorted by name. */
      static const std::vector<Entry> &
      entries()
      {
        return storage();
      }

      /** "a|b|c": the names for a Patterns::Selection. */
      static std::string
      pattern()
      {
        std::string p;
        for (const auto &e : storage())
          p += (p.empty() ? "" : "|") + e.name;
        return p;
      }

      /** Help text listing every plugin with its description. */
      static std::string
      documentation(const std::string &intro)
      {
        std::string d = intro + " The following plugins are available:";
        for (const auto &e : storage())
          d += "\n\n`" + e.name + "': " + e.description;
        return d;
      }

      /**
       * Declare the selection entry and the parameters of every plugin, each
       * in its own subsection.
       */
      static void
      declare_parameters(dealii::ParameterHandler &prm)
      {
        const unsigned int levels =
          enter_path(prm, Interface::registry_section);
        const auto &list = storage();
        // the interface's default, or the first plugin while that one is
        // not registered (e.g. a build without it)
        std::string default_name = list.front().name;
        for (const auto &e : list)
          if (e.name == Interface::default_plugin())
            default_name = e.name;
        prm.declare_entry(Interface::registry_entry,
                          default_name,
                          dealii::Patterns::Selection(pattern()),
                          documentation(Interface::selection_documentation()));
        Interface::declare_common_parameters(prm);
        for (const auto &e : list)
          {
            prm.enter_subsection(section_name(e.name));
            e.declare(prm);
            prm.leave_subsection();
          }
        leave_path(prm, levels);
      }

      /** The name of the selected plugin. */
      static std::string
      selected(dealii::ParameterHandler &prm)
      {
        const unsigned int levels =
          enter_path(prm, Interface::registry_section);
        const std::string name = prm.get(Interface::registry_entry);
        leave_path(prm, levels);
        return name;
      }

      /**
       * Create the plugin selected in @p prm and let it parse its own
       * subsection.
       */
      static std::unique_ptr<Interface>
      create(dealii::ParameterHandler &prm)
      {
        return create(prm, selected(prm));
      }

      /** Create the plugin called @p name and let it parse its subsection. */
      static std::unique_ptr<Interface>
      create(dealii::ParameterHandler &prm, const std::string &name)
      {
        for (const auto &e : storage())
          if (e.name == name)
            {
              std::unique_ptr<Interface> plugin = e.create();
              {
                const unsigned int levels =
                  enter_path(prm, Interface::registry_section);
                ParsePathScope scope(Interface::registry_section);
                plugin->parse_common_parameters(prm);
                leave_path(prm, levels);
              }
              std::string path = Interface::registry_section;
              path += (path.empty() ? "" : "/") + section_name(name);
              const unsigned int levels = enter_path(prm, path);
              {
                ParsePathScope scope(path);
                plugin->parse_parameters(prm);
              }
              leave_path(prm, levels);
              return plugin;
            }
        AssertThrow(false,
                    dealii::ExcMessage("No plugin called '" + name +
                                       "' is registered for '" +
                                       Interface::registry_entry +
                                       "'; available: " + pattern()));
        return nullptr;
      }

    private:
      static std::vector<Entry> &
      storage()
      {
        static std::vector<Entry> list;
        return list;
      }
    };
  } // namespace plugins
} // namespace masonry

#define MASONRY_PLUGIN_CONCAT_(a, b) a##b
#define MASONRY_PLUGIN_CONCAT(a, b) MASONRY_PLUGIN_CONCAT_(a, b)

/**
 * Register @p classname as a plugin of @p interface under @p name. Use once,
 * at namespace scope, in the plugin's .cc file.
 */
#define MASONRY_REGISTER_PLUGIN(interface, classname, name, description)     \
  namespace                                                                  \
  {                                                                          \
    const bool MASONRY_PLUGIN_CONCAT(masonry_plugin_registered_, __LINE__) = \
      masonry::plugins::Registry<interface>::add(                            \
        name,                                                                \
        description,                                                         \
        &classname::declare_parameters,                                      \
        []() -> std::unique_ptr<interface> {                                 \
          return std::make_unique<classname>();                              \
        });                                                                  \
  }

#endif

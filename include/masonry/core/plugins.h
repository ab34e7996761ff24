/**
 * @file
 * The plugin registry, in the style of ASPECT's `plugins.h`.
 *
 * Every pluggable subsystem (analysis, geometry model, LP solver, ...) has an
 * abstract interface class that names where its parameters live:
 *
 * @code
 * class Interface : public plugins::InterfaceBase
 * {
 * public:
 *   // the family's descriptor: where its selection stands, its default
 *   static constexpr const char *registry_section = "Geometry model";
 *   static constexpr const char *registry_entry   = "Model name";
 *   static const char *default_plugin();             // the default selection
 *   static std::string selection_documentation();    // help text of the entry
 *   // only where the family's plugins share entries (InterfaceBase's
 *   // defaults declare and read none):
 *   static void declare_common_parameters(dealii::ParameterHandler &prm);
 *   void parse_common_parameters(dealii::ParameterHandler &prm) override;
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
 *
 * <h3>Families with a list of plugins</h3>
 *
 * A family of which a run uses any number of plugins at once (outputs, like
 * ASPECT's `List of postprocessors`) says so in its interface:
 *
 * @code
 *   static constexpr bool multiple_selection = true;
 *   static const char *default_plugin(); // "a, b, c": the default list
 *   // optional: plugins that must run before this one
 *   virtual std::vector<std::string> required_plugins() const;
 * @endcode
 *
 * Its selection entry is then a comma-separated list (a
 * Patterns::MultipleSelection of the registered names; an empty list selects
 * none), and create_selected() creates and parses every listed plugin, in
 * the order of the list, after the plugins each one requires (added if the
 * list does not name them). Names in the default list that are not
 * registered are left out of the default. Plugins of an `Additional shared
 * libraries` file register like the built-in ones and can be listed.
 *
 * <h3>Families whose plugins share one subsection</h3>
 *
 * A family whose selection entry and plugin entries stand together in one
 * subsection (the wallette's `Protocol', `Damage integration' and `Linear
 * solver' in `subsection Wallette', next to the analysis's own entries)
 * says
 *
 * @code
 *   static constexpr bool shared_subsection = true;
 * @endcode
 *
 * Its plugins then declare and parse their entries in the family's
 * subsection itself, not in one of their own; their names must not clash.
 */
#ifndef masonry_core_plugins_h
#define masonry_core_plugins_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
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
     * The base of every plugin family's interface (as ASPECT's
     * Plugins::InterfaceBase): a virtual destructor and the hooks that
     * declare and read parameters, which do nothing unless a family or a
     * plugin overrides them. A family's interface derives from it and adds
     * its descriptor (`registry_section`, `registry_entry`,
     * `default_plugin()`, `selection_documentation()`; see the top of this
     * file); a plugin overrides parse_parameters() to read its own
     * subsection.
     */
    class InterfaceBase
    {
    public:
      virtual ~InterfaceBase() = default;

      /** Entries shared by every plugin of the family, declared in the
       * family's subsection: none by default. A family that has some
       * declares a static function of this name in its interface. */
      static void
      declare_common_parameters(dealii::ParameterHandler &)
      {}

      /** Read the shared entries: nothing by default. */
      virtual void
      parse_common_parameters(dealii::ParameterHandler &)
      {}

      /** Read the plugin's own entries: nothing by default. */
      virtual void
      parse_parameters(dealii::ParameterHandler &)
      {}
    };

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

    namespace internal
    {
      /** Whether @p Interface declares `multiple_selection = true`. */
      template <class Interface, class = void>
      struct IsMultiple : std::false_type
      {};

      template <class Interface>
      struct IsMultiple<Interface,
                        std::void_t<decltype(Interface::multiple_selection)>>
        : std::integral_constant<bool, Interface::multiple_selection>
      {};

      /** Whether @p Interface declares `shared_subsection = true`. */
      template <class Interface, class = void>
      struct IsShared : std::false_type
      {};

      template <class Interface>
      struct IsShared<Interface,
                      std::void_t<decltype(Interface::shared_subsection)>>
        : std::integral_constant<bool, Interface::shared_subsection>
      {};

      /** Whether @p Interface has `required_plugins() const`. */
      template <class Interface, class = void>
      struct HasRequired : std::false_type
      {};

      template <class Interface>
      struct HasRequired<Interface,
                         std::void_t<decltype(std::declval<const Interface &>()
                                                .required_plugins())>>
        : std::true_type
      {};

      /** Split a comma-separated list, dropping blanks around names. */
      std::vector<std::string>
      split_list(const std::string &text);

      /**
       * Throw masonry::ExcParameter for @p entry (in @p section) with
       * @p message (out of line: keeps parameters.h out of this header);
       * never returns.
       */
      void
      throw_parameter_error(const std::string &section,
                            const std::string &entry,
                            const std::string &message);
    } // namespace internal

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
                         static_cast<Declare>(&Registry::declare_parameters)});
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
        declare_parameters(prm, Interface::registry_section);
      }

      /**
       * The same in @p section instead of the family's own subsection (a
       * second member of the family, e.g. `Mortar material' next to `Brick
       * material').
       */
      static void
      declare_parameters(dealii::ParameterHandler &prm,
                         const std::string        &section)
      {
        const unsigned int levels = enter_path(prm, section);
        const auto        &list   = storage();
        // the interface's default, or the first plugin while that one is
        // not registered (e.g. a build without it)
        if constexpr (internal::IsMultiple<Interface>::value)
          {
            // the default list without names that are not registered
            std::string default_list;
            for (const auto &name :
                 internal::split_list(Interface::default_plugin()))
              for (const auto &e : list)
                if (e.name == name)
                  default_list += (default_list.empty() ? "" : ", ") + name;
            prm.declare_entry(Interface::registry_entry,
                              default_list,
                              dealii::Patterns::MultipleSelection(pattern()),
                              documentation(
                                Interface::selection_documentation()));
          }
        else
          {
            std::string default_name = list.front().name;
            for (const auto &e : list)
              if (e.name == Interface::default_plugin())
                default_name = e.name;
            prm.declare_entry(Interface::registry_entry,
                              default_name,
                              dealii::Patterns::Selection(pattern()),
                              documentation(
                                Interface::selection_documentation()));
          }
        Interface::declare_common_parameters(prm);
        for (const auto &e : list)
          if constexpr (internal::IsShared<Interface>::value)
            e.declare(prm);
          else
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
        return selected(prm, Interface::registry_section);
      }

      /** The name of the plugin selected in @p section. */
      static std::string
      selected(dealii::ParameterHandler &prm, const std::string &section)
      {
        const unsigned int levels = enter_path(prm, section);
        const std::string  name   = prm.get(Interface::registry_entry);
        leave_path(prm, levels);
        return name;
      }

      /**
       * A family with a list of plugins: the names listed in @p prm, in
       * their order (a name listed twice is an error naming the entry).
       */
      static std::vector<std::string>
      selected_list(dealii::ParameterHandler &prm)
      {
        static_assert(internal::IsMultiple<Interface>::value,
                      "selected_list() is for families with a list");
        const std::vector<std::string> names =
          internal::split_list(selected(prm));
        for (unsigned int i = 0; i < names.size(); ++i)
          for (unsigned int j = 0; j < i; ++j)
            if (names[i] == names[j])
              internal::throw_parameter_error(Interface::registry_section,
                                              Interface::registry_entry,
                                              "'" + names[i] +
                                                "' is listed twice");
        return names;
      }

      /**
       * A family with a list of plugins: create every plugin listed in
       * @p prm and let each parse its subsection. Each comes after the
       * plugins its required_plugins() names (created too if not listed);
       * otherwise the order is that of the list. Unlisted plugins are not
       * created.
       */
      static std::vector<std::pair<std::string, std::unique_ptr<Interface>>>
      create_selected(dealii::ParameterHandler &prm)
      {
        std::vector<std::pair<std::string, std::unique_ptr<Interface>>> result;
        std::vector<std::string> in_progress;
        std::function<void(const std::string &, const std::string &)> visit =
          [&](const std::string &name, const std::string &required_by) {
            for (const auto &r : result)
              if (r.first == name)
                return;
            for (const auto &p : in_progress)
              AssertThrow(p != name,
                          dealii::ExcMessage(
                            "The plugins required by '" + name + "' for '" +
                            Interface::registry_entry + "' form a cycle."));
            if (!required_by.empty() && !is_registered(name))
              internal::throw_parameter_error(Interface::registry_section,
                                              Interface::registry_entry,
                                              "'" + required_by +
                                                "' requires '" + name +
                                                "', which is not registered");
            in_progress.push_back(name);
            std::unique_ptr<Interface> plugin = create(prm, name);
            if constexpr (internal::HasRequired<Interface>::value)
              for (const std::string &r : plugin->required_plugins())
                visit(r, name);
            in_progress.pop_back();
            result.emplace_back(name, std::move(plugin));
          };
        for (const auto &name : selected_list(prm))
          visit(name, "");
        return result;
      }

      /** Whether a plugin called @p name is registered. */
      static bool
      is_registered(const std::string &name)
      {
        for (const auto &e : storage())
          if (e.name == name)
            return true;
        return false;
      }

      /**
       * Create the plugin selected in @p prm and let it parse its own
       * subsection.
       */
      static std::unique_ptr<Interface>
      create(dealii::ParameterHandler &prm)
      {
        static_assert(!internal::IsMultiple<Interface>::value,
                      "a family with a list: use create_selected()");
        return create(prm, selected(prm));
      }

      /** Create the plugin called @p name and let it parse its subsection. */
      static std::unique_ptr<Interface>
      create(dealii::ParameterHandler &prm, const std::string &name)
      {
        return create(prm, name, Interface::registry_section);
      }

      /** Create the plugin called @p name and let it parse its subsection
       * of @p section (see declare_parameters(prm, section)). */
      static std::unique_ptr<Interface>
      create(dealii::ParameterHandler &prm,
             const std::string        &name,
             const std::string        &section)
      {
        for (const auto &e : storage())
          if (e.name == name)
            {
              std::unique_ptr<Interface> plugin = e.create();
              {
                const unsigned int levels = enter_path(prm, section);
                ParsePathScope     scope(section);
                plugin->parse_common_parameters(prm);
                leave_path(prm, levels);
              }
              std::string path = section;
              if constexpr (!internal::IsShared<Interface>::value)
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

// A plugin family whose selection entry is a list (like `List of
// postprocessors`): the default list leaves out unregistered names, every
// listed plugin is created and parses its own subsection, a plugin's
// required plugins are created before it even if not listed, unlisted
// plugins are not created, and a name listed twice or not registered is an
// error naming the entry.
#include <masonry/core/parameters.h>
#include <masonry/core/plugins.h>

#include <iostream>

namespace
{
  unsigned int n_created = 0;

  class Output
  {
  public:
    static constexpr const char *registry_section   = "Test outputs";
    static constexpr const char *registry_entry     = "List of outputs";
    static constexpr bool        multiple_selection = true;
    static const char *
    default_plugin()
    {
      return "gamma, not registered, alpha";
    }
    static std::string
    selection_documentation()
    {
      return "Outputs.";
    }
    static void
    declare_common_parameters(dealii::ParameterHandler &)
    {}
    Output()
    {
      ++n_created;
    }
    virtual ~Output() = default;
    virtual void
    parse_common_parameters(dealii::ParameterHandler &)
    {}
    virtual void
    parse_parameters(dealii::ParameterHandler &prm)
    {
      value = prm.get_integer("Value");
    }
    virtual std::vector<std::string>
    required_plugins() const
    {
      return {};
    }
    static void
    declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.declare_entry("Value", "1", dealii::Patterns::Integer(), "A value.");
    }
    int value = 0;
  };

  class Alpha : public Output
  {};
  class Beta : public Output
  {};
  /** Needs beta's result. */
  class Gamma : public Output
  {
  public:
    std::vector<std::string>
    required_plugins() const override
    {
      return {"beta"};
    }
  };
  /** Requires a plugin that does not exist. */
  class Broken : public Output
  {
  public:
    std::vector<std::string>
    required_plugins() const override
    {
      return {"no such output"};
    }
  };
} // namespace

MASONRY_REGISTER_PLUGIN(Output, Alpha, "alpha", "First.")
MASONRY_REGISTER_PLUGIN(Output, Beta, "beta", "Second.")
MASONRY_REGISTER_PLUGIN(Output, Gamma, "gamma", "Third, needs beta.")
MASONRY_REGISTER_PLUGIN(Output, Broken, "broken", "Needs a missing one.")

using Registry = masonry::plugins::Registry<Output>;

void
check(const std::string &input)
{
  dealii::ParameterHandler prm;
  Registry::declare_parameters(prm);
  n_created = 0;
  std::cout << "input: " << (input.empty() ? "(defaults)" : input) << "\n";
  try
    {
      prm.parse_input_from_string("subsection Test outputs\n" + input +
                                  "\nend\n");
      const auto outputs = Registry::create_selected(prm);
      std::cout << "  created " << n_created << ":";
      for (const auto &[name, plugin] : outputs)
        std::cout << " " << name << "=" << plugin->value;
      std::cout << "\n";
    }
  catch (const std::exception &e)
    {
      std::cout << "  error: " << masonry::one_line_message(e) << "\n";
    }
}

int
main()
{
  {
    dealii::ParameterHandler prm;
    Registry::declare_parameters(prm);
    prm.enter_subsection("Test outputs");
    std::cout << "default list: " << prm.get("List of outputs") << "\n";
    prm.leave_subsection();
  }
  check("");
  check("set List of outputs = alpha\n"
        "subsection Alpha\n set Value = 7\nend");
  check("set List of outputs = gamma, beta");
  check("set List of outputs = beta, gamma, alpha\n"
        "subsection Beta\n set Value = 3\nend");
  check("set List of outputs =");
  check("set List of outputs = alpha, alpha");
  check("set List of outputs = alpha, delta");
  check("set List of outputs = broken");
}

// How mbc's help reads: the usage line with the command's full name,
// descriptions wrapped to 80 columns, one blank line between groups.
#pragma once

#include <CLI/CLI.hpp>

namespace mbc::runner {

class HelpFormatter : public CLI::Formatter {
public:
  HelpFormatter() {
    column_width(30);
    label("Positionals", "Arguments");
  }

  std::string make_usage(const CLI::App* app, std::string name) const override;
  std::string make_help(const CLI::App* app, std::string name,
                        CLI::AppFormatMode mode) const override;
  std::string make_subcommand(const CLI::App* sub) const override;
  std::string make_option_opts(const CLI::Option* opt) const override;
  std::string make_option_name(const CLI::Option* opt,
                               bool isPositional) const override;

protected:
  std::string make_option(const CLI::Option* opt,
                          bool isPositional) const override;
};

/// Gives `app` and the commands added to it afterwards mbc's help layout.
void useHelpFormatter(CLI::App& app);

} // namespace mbc::runner

#include "runner/help_formatter.h"

#include <sstream>

namespace mbc::runner {

namespace {

constexpr std::size_t kLineWidth = 80;

// "  NAME        description wrapped under itself"
std::string entry(const std::string& name, const std::string& description,
                  std::size_t column) {
  std::string out = "  " + name;
  if (out.size() + 1 > column) {
    out += "\n" + std::string(column, ' ');
  } else {
    out.resize(column, ' ');
  }
  std::size_t lineLength = column;
  std::istringstream words(description);
  bool first = true;
  for (std::string word; words >> word;) {
    if (!first && lineLength + 1 + word.size() > kLineWidth) {
      out += "\n" + std::string(column, ' ');
      lineLength = column;
      first = true;
    }
    if (!first) {
      out += ' ';
      ++lineLength;
    }
    out += word;
    lineLength += word.size();
    first = false;
  }
  return out + "\n";
}

std::string fullName(const CLI::App* app) {
  std::string name = app->get_name();
  for (const CLI::App* p = app->get_parent(); p != nullptr;
       p = p->get_parent()) {
    name = p->get_name() + " " + name;
  }
  return name;
}

} // namespace

std::string HelpFormatter::make_usage(const CLI::App* app, std::string) const {
  std::string out = "Usage: " + fullName(app);
  if (!app->get_subcommands({}).empty()) {
    return out + " COMMAND [OPTIONS]\n";
  }
  out += " [OPTIONS]";
  for (const CLI::Option* opt : app->get_options()) {
    if (opt->get_positional()) {
      out += " " + opt->get_name(true, false) + "...";
    }
  }
  return out + "\n";
}

std::string HelpFormatter::make_help(const CLI::App* app, std::string name,
                                     CLI::AppFormatMode mode) const {
  std::string out =
      make_description(app) + make_usage(app, name) + make_positionals(app);
  for (const std::string& group : app->get_groups()) {
    std::vector<const CLI::Option*> opts =
        app->get_options([&group](const CLI::Option* opt) {
          return opt->get_group() == group && opt->nonpositional();
        });
    if (!group.empty() && !opts.empty()) {
      out += make_group(group, false, opts);
    }
  }
  return out + make_subcommands(app, mode) + "\n" + make_footer(app);
}

std::string HelpFormatter::make_subcommand(const CLI::App* sub) const {
  return entry(sub->get_name(), sub->get_description(), get_column_width());
}

std::string HelpFormatter::make_option_opts(const CLI::Option* opt) const {
  if (opt->get_positional()) {
    return "...";
  }
  if (opt->get_type_size() == 0 || opt->get_type_name().empty()) {
    return "";
  }
  const std::string type = opt->get_type_name();
  return (type.starts_with("[") ? "" : " ") + type;
}

// A flag's default value ("--block-skip{1}") is not part of its name.
std::string HelpFormatter::make_option_name(const CLI::Option* opt,
                                            bool isPositional) const {
  std::string name = CLI::Formatter::make_option_name(opt, isPositional);
  for (std::size_t open = name.find('{'); open != std::string::npos;
       open = name.find('{')) {
    name.erase(open, name.find('}', open) - open + 1);
  }
  // "-j, --jobs", as man pages write them (help2man reads them so).
  for (std::size_t comma = name.find(','); comma != std::string::npos;
       comma = name.find(',', comma + 2)) {
    name.insert(comma + 1, " ");
  }
  return name;
}

std::string HelpFormatter::make_option(const CLI::Option* opt,
                                       bool isPositional) const {
  return entry(make_option_name(opt, isPositional) + make_option_opts(opt),
               make_option_desc(opt), get_column_width());
}

void useHelpFormatter(CLI::App& app) {
  app.formatter(std::make_shared<HelpFormatter>());
}

} // namespace mbc::runner

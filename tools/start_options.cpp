#include "start_options.hpp"

#include <fmt/format.h>

#include "cli_common.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/model/pascal_2014/paper_examples.hpp"

namespace stickslip::cli {

namespace {

// "NAME=VALUE" texts of the option `field` ("set", "guess").
NamedValues Assignments(const std::vector<std::string>& texts, const char* field) {
  NamedValues values;
  for (const std::string& text : texts) {
    const auto equals = text.find('=');
    if (equals == std::string::npos) {
      throw InvalidInput(field, fmt::format("'{}'", text), "NAME=VALUE");
    }
    const std::string name = text.substr(0, equals);
    values.emplace_back(name, ParseNumber(name, text.substr(equals + 1), SetKeyRange(name)));
  }
  return values;
}

}  // namespace

void AddStartOptions(CLI::App& cmd, StartFlags* flags, StartOptions which) {
  const bool orbit = which == StartOptions::kOrbit;
  cmd.add_option("--preset", flags->preset,
                 orbit ? "a paper orbit: " + PaperExampleNames() + " (data, signature and printed values as guess)"
                       : "start from a paper example's printed data and initial state: " + PaperExampleNames());
  cmd.add_option("--point", flags->point,
                 orbit ? "start from a labelled point of a continuation run under --results: its orbit type, data "
                         "and orbit (RUN:LABEL, e.g. paper-5.1-omega-up:TR2), or a [model]'s (its model from the run file its "
                         "summary.json names; then no other start option)"
                       : "start from a labelled point of a continuation run under --results instead of a preset: "
                         "its data, its orbit's initial state and phase (RUN:LABEL, e.g. paper-5.1-omega-up:TR2)")
      ->type_name("RUN:LABEL");
  cmd.add_option("--set", flags->set, SetKeysHelp())->type_name("KEY=VALUE");
  if (!orbit) return;
  cmd.add_option("--signature", flags->signature,
                 "orbit type, e.g. \"slip- slip+ stick slip+\" or \"slip- stick slip- / antisymmetric\" "
                 "(options after '/': antisymmetric, period K)");
  cmd.add_option("--guess", flags->guess,
                 "starting value of any orbit variable: x10, x20, v10, phi, d1..dn (durations, scaled time, "
                 ">= 0), chi, eta, omega, u_s, u_r")
      ->type_name("NAME=VALUE");
  cmd.add_option("--free", flags->free, "release a variable (usually a parameter: chi, eta, omega, u_s, u_r) as an unknown")
      ->type_name("NAME");
  cmd.add_option("--fix", flags->fix, "hold a variable (phi, d1..dn, x10, ...) at its guess, or at VALUE")
      ->type_name("NAME[=VALUE]");
  cmd.add_flag("--tie-u_r", flags->tie_u_r, "hold u_r = u_s (abnormal stops need it, eq. 25)");
}

StartInput ToStartInput(const StartFlags& flags) {
  StartInput input;
  input.preset = flags.preset;
  input.signature = flags.signature;
  if (!flags.point.empty()) input.restart = ReadRestartPoint(flags.results, flags.point);
  input.set = Assignments(flags.set, "set");
  input.guess = Assignments(flags.guess, "guess");
  input.free = flags.free;
  for (const std::string& text : flags.fix) {
    const auto equals = text.find('=');
    if (equals == std::string::npos) {
      input.fix.push_back({text, std::nullopt});
    } else {
      const std::string name = text.substr(0, equals);
      input.fix.push_back({name, ParseNumber(name, text.substr(equals + 1), SetKeyRange(name))});
    }
  }
  input.tie_u_r = flags.tie_u_r;
  return input;
}

}  // namespace stickslip::cli

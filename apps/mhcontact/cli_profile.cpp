// `mhcontact profile convert` and `mhcontact profile info` (docs/profiles.md §8).
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <memory>
#include <ostream>

#include "cli.hpp"
#include "core/errors.hpp"
#include "core/units.hpp"
#include "core/numfmt.hpp"
#include "output/pair_tables.hpp"
#include "output/profile_file.hpp"
#include "profile/curve.hpp"
#include "profile/rail_cant.hpp"
#include "profile/read.hpp"

namespace mh {

void add_profile_read_options(CLI::App& app, ProfileReadOptions& opt) {
  app.add_option_function<std::string>(
         "--format", [&opt](const std::string& s) { opt.format = parse_profile_format(s); },
         "input format (default auto: by extension, else by content)")
      ->check(CLI::IsMember({"auto", "simpack", "miniprof", "table", "vampire"}));
  app.add_option_function<std::string>(
         "--kind",
         [&opt](const std::string& s) { opt.kind = s == "wheel" ? ProfileKind::Wheel : ProfileKind::Rail; },
         "wheel or rail (default: from the file header/extension, else the shape)")
      ->check(CLI::IsMember({"wheel", "rail"}));
  app.add_flag("--mirror-y", opt.mirror_y, "mirror y after the format's own transformations");
  app.add_flag("--mirror-z", opt.mirror_z, "mirror z after the format's own transformations");
  app.add_option("--scale", opt.scale, "multiply file lengths by S to get mm (default 1)")
      ->check(CLI::PositiveNumber);
  app.add_option("--vampire-side", opt.vampire_side, "VAMPIRE files: which side to read (default right)")
      ->check(CLI::IsMember({"left", "right"}));
  app.add_option_function<std::string>(
         "--cleanup", [&opt](const std::string& s) { opt.cleanup = parse_profile_cleanup(s); },
         "clean-up where contact can happen: envelope (default: folds and loops replaced by the outer "
         "envelope, with a warning), strict (reject any fold larger than 0.05 mm jitter) or off (drop nothing)")
      ->check(CLI::IsMember({"envelope", "strict", "off"}));
  app.add_option("--section", opt.section,
                 "multi-profile MiniProf files (.mpt): read profile K ([Profile<K>Info]); default: the only one "
                 "that can be a wheel or a rail (--kind narrows it), else the file is refused with the list")
      ->check(CLI::Range(1, 1000000));
  app.add_flag("--no-check", [&opt](std::int64_t) { opt.check = false; },
               "skip the shape plausibility checks (flange side, upside down, kind)");
}

namespace {

std::string mm(double v_m) { return format_number(v_m * units::per_mm); }

void print_info(const Profile& p, bool json, ProfileNoise noise, std::ostream& out) {
  double ymin = p.y.front(), ymax = p.y.back();
  std::vector<std::string> info_warnings;  // from the checks below, after the reader's own
  nlohmann::ordered_json j;
  j["file"] = p.source;
  j["format"] = p.format;
  j["kind"] = to_string(p.kind);
  j["points"] = p.size();
  j["y_min_mm"] = ymin * units::per_mm;
  j["y_max_mm"] = ymax * units::per_mm;
  std::string text = "file: " + p.source + "\nformat: " + p.format + "\nkind: " + to_string(p.kind) +
                     "\npoints: " + std::to_string(p.size()) + "\ny_range_mm: " + mm(ymin) + " " + mm(ymax) + "\n";
  if (p.kind == ProfileKind::Rail) {
    const RailLandmarks L = rail_landmarks(p);
    j["head_top_y_mm"] = L.y_top * units::per_mm;
    j["head_top_z_mm"] = L.z_top * units::per_mm;
    text += "head_top_mm: y " + mm(L.y_top) + " z " + mm(L.z_top) + "\n";
    if (!p.face_y.empty()) {  // a vertical gauge face (profiles.md §3)
      j["gauge_face"] = {{"points", p.face_y.size()},
                         {"y_mm", p.face_y.front() * units::per_mm},
                         {"z_foot_mm", p.face_z.back() * units::per_mm}};
      text += "gauge_face_mm: y " + mm(p.face_y.front()) + " from z " + mm(p.z.front()) + " down to " +
              mm(p.face_z.back()) + " (" + std::to_string(p.face_y.size()) + " points besides those above)\n";
    }
    // The cant of the head (profiles.md "Cant estimate"): positive leaning to the gauge side.
    const RailCantCheck cc = check_rail_cant(p, Inclination::AsIs);
    j["cant"] = cant_json(cc.used);
    if (cc.used.found)
      text += "cant: " + format_number(std::round(cc.used.angle / units::deg * 1e3) / 1e3 + 0.0) + " deg (" +
              cant_ratio(cc.used.angle) + "; positive: canted towards the gauge side), standard error " +
              format_number(std::round(cc.used.std_error / units::deg * 1e3) / 1e3 + 0.0) + " deg" +
              (cc.used.confident ? "" : ", not confident: " + cc.used.why) + "\n";
    else
      text += "cant: not estimated (" + cc.used.why + ")\n";
    info_warnings = cc.warnings;
    if (L.has_gauge) {
      j["gauge_point_y_mm"] = L.y_gauge * units::per_mm;
      j["gauge_point_z_mm"] = L.z_gauge * units::per_mm;
      if (L.gauge_at_widest) j["gauge_point_at_widest"] = true;
      text += std::string(L.gauge_at_widest ? "gauge_point_mm (widest point: the face turns under above 14 mm below the top)"
                                            : "gauge_point_mm (14 mm below the top)") +
              ": y " + mm(L.y_gauge) + " z " + mm(L.z_gauge) + "\n";
    } else {
      j["gauge_point_y_mm"] = nullptr;
      j["gauge_point_z_mm"] = nullptr;
      text += "gauge_point_mm: none (profile does not reach 14 mm below the top on the gauge side)\n";
    }
  } else if (p.kind == ProfileKind::Wheel) {
    // How y = 0 was put on the taping line (a wheel measured from its flange back), or as in the file.
    j["taping_line"] = p.taping_line.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(p.taping_line);
    text += "taping_line: " + (p.taping_line.empty() ? std::string("y = 0 as in the file") : p.taping_line) + "\n";
    const WheelLandmarks L = wheel_landmarks(p);
    j["flange_tip_y_mm"] = L.y_tip * units::per_mm;
    j["flange_tip_z_mm"] = L.z_tip * units::per_mm;
    text += "flange_tip_mm: y " + mm(L.y_tip) + " z " + mm(L.z_tip) + "\n";
    const WheelMeasures M = wheel_measures(p);
    if (M.valid) {
      auto r3 = [](double v_m) { return std::round(v_m * 1e6) / 1e3; };  // mm to 1 µm
      j["wheel_measures_mm"] = {{"Sh", r3(M.Sh)}, {"Sd", r3(M.Sd)}, {"qR", r3(M.qR)}};
      text += "wheel_measures_mm (EN 15313): Sh " + format_number(r3(M.Sh)) + " Sd " + format_number(r3(M.Sd)) +
              " qR " + format_number(r3(M.qR)) + "\n";
    } else {
      j["wheel_measures_mm"] = nullptr;
      text += "wheel_measures_mm: none (" + M.why + ")\n";
    }
  }
  if (!p.file_measures.empty()) {
    nlohmann::ordered_json m;
    text += "file_measures:";
    for (const auto& kv : p.file_measures) {
      m[kv.first] = kv.second;
      text += " " + kv.first + "=" + kv.second;
    }
    text += "\n";
    j["file_measures"] = m;
  }
  if (!p.cleanup.mode.empty()) {
    const CleanupReport& c = p.cleanup;
    nlohmann::ordered_json cj;
    cj["mode"] = c.mode;
    cj["duplicates_removed"] = c.duplicates;
    cj["jitter_points_dropped"] = c.jitter;
    cj["folds_removed"] = c.folds;
    cj["fold_points_dropped"] = c.fold_points;
    cj["crossing_points_added"] = c.crossings;
    if (c.folds) {
      cj["folds_y_from_mm"] = c.y_from_mm;
      cj["folds_y_to_mm"] = c.y_to_mm;
      cj["largest_fold_mm"] = c.largest_fold_mm;
    }
    j["cleanup"] = cj;
    text += "cleanup: " + c.mode + ", " + std::to_string(c.duplicates) + " duplicates, " + std::to_string(c.jitter) +
            " jitter points, " + std::to_string(c.folds) + " folds (" + std::to_string(c.fold_points) +
            " points dropped, " + std::to_string(c.crossings) + " crossing points added)";
    if (c.folds)
      text += " at y " + format_number(std::round(c.y_from_mm * 1e3) / 1e3) + " … " +
              format_number(std::round(c.y_to_mm * 1e3) / 1e3) + " mm, largest step back " +
              format_number(std::round(c.largest_fold_mm * 1e3) / 1e3) + " mm";
    text += "\n";
  }
  // Measured or exact (profiles.md "Measured or exact"): the curvature fit's decision.
  try {
    CurveOptions co;
    co.noise = noise;
    const ProfileCurve curve(p, co);
    j["noise"] = noise_json(curve.noise());
    j["fit_window_mm"] = curve.window_used() * units::per_mm;
    text += "noise: " + curve.noise().reason + "; fit window " + mm(curve.window_used()) + " mm\n";
    // Smoothing for contact (§7), by the default rule ("auto": from the profile's own noise).
    const std::optional<SmoothedProfile> sp = smooth_for_contact(p, curve.noise(), std::nullopt);
    if (sp) {
      j["contact_smoothing_mm"] = std::round(sp->L * 1e6) / 1e3;
      j["contact_smoothing_local_min_mm"] = std::round(sp->L_local_min * 1e6) / 1e3;
      text += "smoothing for contact (grid methods, auto): L = " + format_number(std::round(sp->L * 1e5) / 100) +
              " mm from the noise " + format_number(std::round(curve.noise().sigma * 1e8) / 100) + " µm" +
              (sp->at_bound ? " (at its bound)" : "") +
              (sp->L_local_min < sp->L ? "; shortened where it would remove geometry above the noise, to as little as " +
                                             format_number(std::round(sp->L_local_min * 1e5) / 100) + " mm, between y " +
                                             format_number(std::round(sp->local_from * 1e4) / 10) + " and " +
                                             format_number(std::round(sp->local_to * 1e4) / 10) + " mm"
                                       : std::string()) +
              "\n";
    } else {
      j["contact_smoothing_mm"] = 0;
      text += "smoothing for contact (grid methods): none (" +
              std::string(curve.noise().measured ? "no noise estimate" : "an exact profile is never smoothed") + ")\n";
    }
  } catch (const InputError& e) {
    j["noise"] = nullptr;
    text += std::string("noise: not classified (") + e.what() + ")\n";
  }
  j["sha256"] = p.checksum;
  std::vector<std::string> all = p.warnings;
  all.insert(all.end(), info_warnings.begin(), info_warnings.end());
  j["warnings"] = all;
  text += "sha256: " + p.checksum + "\n";
  for (const auto& w : all) text += "warning: " + w + "\n";
  if (json) out << j.dump(2) << "\n";
  else out << text;
}

}  // namespace

void add_profile_io_commands(CLI::App& profile, CliContext& ctx) {
  {
    auto opt = std::make_shared<ProfileReadOptions>();
    auto in = std::make_shared<std::string>();
    auto outp = std::make_shared<std::string>();
    CLI::App* c = profile.add_subcommand("convert", "read a profile file (cleaned, see --cleanup) and write it in any format it reads");
    c->add_option("IN", *in, "input profile file")->required();
    c->add_option("-o,--output", *outp, "output file: .csv/.txt/.dat (y_mm, z_mm; z up), .prr/.prw (SIMPACK), .ban/.whl (MiniProf), "
                   ".rail/.wheel (GENSYS) or .rai/.whe (VAMPIRE); the extension must match the kind")->required();
    add_profile_read_options(*c, *opt);
    c->callback([opt, in, outp, &ctx]() {
      const Profile p = read_profile(*in, *opt);
      write_profile(p, *outp);
      for (const auto& w : p.warnings) ctx.err << "warning: " << *in << ": " << w << "\n";
      ctx.out << "wrote " << *outp << " (" << to_string(p.kind) << ", " << p.size() + p.face_y.size() << " points"
              << (p.face_y.empty() ? "" : ", " + std::to_string(p.face_y.size()) + " of them on the gauge face") << ")\n";
      ctx.exit_code = kExitOk;
    });
  }
  {
    auto opt = std::make_shared<ProfileReadOptions>();
    auto in = std::make_shared<std::string>();
    auto json = std::make_shared<bool>(false);
    auto noise = std::make_shared<ProfileNoise>(ProfileNoise::Auto);
    CLI::App* c = profile.add_subcommand("info", "print format, kind, point count, y range, landmarks, cant (rails), "
                                                 "measured or exact, warnings");
    c->add_option("IN", *in, "input profile file")->required();
    c->add_flag("--json", *json, "print JSON instead of text");
    c->add_option_function<std::string>(
         "--noise", [noise](const std::string& s) { *noise = parse_profile_noise(s); },
         "measured or exact: auto (default: the fit residual against the rounding of the printed digits), "
         "exact or measured")
        ->check(CLI::IsMember({"auto", "exact", "measured"}));
    add_profile_read_options(*c, *opt);
    c->callback([opt, in, json, noise, &ctx]() {
      const Profile p = read_profile(*in, *opt);
      print_info(p, *json, *noise, ctx.out);
      ctx.exit_code = kExitOk;
    });
  }
}

}  // namespace mh

// A study's file (experiments/studies/<name>.yaml, docs/studies.md): a base profile, the study's
// seeds, the reference settings and the settings to compare, each a set of keys of the base
// replaced (after the study's `common` keys); the profile goals each setting runs (`stages`), its
// report's kind (`report`, report/report_kinds.hpp), the figures drawn from that report's data
// and the folder it writes under DATA (`out`). Every setting becomes a profile of its own, run by
// the profile DAG (workflow/studies.mk); a setting `of` another one with fewer `seeds` is that
// one's results on those seeds (no run). Settings may also be generated: `vary` (one key at a
// time around the reference) or `grid` (every combination of the keys' values); a generated
// setting equal to the reference is the reference's results (`of: reference`). A list (seeds,
// values) may be read from another file, `{file: F, key: a.b}`: the preregistered criteria's
// grid and seeds are read where they were fixed, not copied.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "report/study_base.hpp"

namespace softpack {

struct StudySetting {
  std::string name;
  std::vector<std::pair<std::string, YAML::Node>> set;  ///< dotted key of the profile, new value
  std::string of;                                       ///< "" or the setting whose results it takes
  std::vector<std::uint64_t> seeds;                     ///< its seeds (the study's unless said)
  bool runs() const { return of.empty(); }
};

/// A figure of the study's report: gnuplot `script` drawn from the report's `data` file into
/// `name`.pdf and `name`.png (the script reads the variables `data` and `out`).
struct StudyFigure {
  std::string script, data, name;
};

/// A key the study varies (`vary` or `grid`): its settings, each with the value it sets as written
/// (`vary`: the settings of this key; `grid`: every setting of the grid, in the grid's order).
struct StudyAxis {
  std::string key;                                          ///< dotted key of the profile
  std::vector<std::pair<std::string, std::string>> points;  ///< (value as written, setting name)
  std::string name() const { return key.substr(key.rfind('.') + 1); }  ///< the key's last part (beta)
};

struct Study {
  std::string path, base;
  std::string name;                 ///< `study`
  std::string report;               ///< the report's kind (report/report_kinds.hpp)
  std::vector<std::string> stages;  ///< the profile goals every setting runs (default: tangential)
  std::string out;                  ///< its folder under DATA (default: studies/<name>)
  std::string archive;  ///< `archive`: results the stages reuse where their stamps match ("": none)
  std::vector<StudyFigure> figures;
  YAML::Node base_yaml;  ///< the base profile as read (ConfigNode's checks)
  StudyBase base_kind = StudyBase::profile;  ///< a profile, or the coarse-grain settings (report/study_base.hpp)
  std::vector<std::uint64_t> seeds;
  std::vector<std::pair<std::string, YAML::Node>> common;  ///< replaced in every setting first
  std::vector<double> Fn_delta_n, kt_delta_n;  ///< where Fn and kt are compared
  /// calibrate.b_range: per scene, the fixed Δn range of the calibration report's Eq. 7 fit
  /// ("b on a fixed range", report/calibration_report.hpp); empty for an accuracy study.
  std::map<std::string, std::pair<double, double>> b_range;
  /// radius (the radius study, report/radius_report.hpp): the settings of each variant
  /// ("self_similar", "fixed": radii in increasing order, "reference" among them; "mixed":
  /// soft-soft of two radii), and from which ht / Rs a sliding contact's Ft / Fn is averaged.
  std::map<std::string, std::vector<std::string>> radius_variants;
  double mu_from_ht_over_Rs = 0.0;
  /// nested, optional (`nested.mu_seeds_loaded`): mu_soft at a sliding Δn is averaged over the
  /// seeds whose contact carries a normal force at every sliding point of it, when at least this
  /// many do; 0 (the radius study's rule): every seed must.
  std::size_t mu_seeds_loaded = 0;
  /// nested (report/nested_report.hpp): the setting every other one is compared with (the
  /// content resolved); the radius section's mu_from_ht_over_Rs is nested's too.
  std::string nested_against;
  std::string criteria;          ///< `criteria`: the criteria file a judging kind applies ("": none)
  std::vector<StudyAxis> vary;   ///< `vary`: each key with its settings, in the file's order
  std::vector<StudyAxis> grid;   ///< `grid`: its keys, the last varying fastest
  StudySetting reference;                      ///< name "reference", its own seeds
  std::vector<StudySetting> settings;
  const StudySetting& setting(const std::string& name) const;  ///< reference or a setting; InputError
};

/// Reads and checks the study file: known keys, seeds >= 101 (held out from the paper's 1-7),
/// settings' seeds a subset of their source's, `of` naming a running setting, and every
/// setting's profile valid (it is generated and read as the stages read it). InputError names
/// the file, line and key.
Study read_study(const std::string& path);

/// What a setting changes, for the reports: "key = value, ..." ("(the base, FILE)" for none;
/// "S on n of its seeds" for a setting `of` S).
std::string setting_changes(const Study& study, const StudySetting& setting);

/// The profile of a running setting (or the reference): the base with the keys of `set`
/// replaced, its `profile` name and `seeds`; a header says where it comes from.
std::string setting_profile_text(const Study& study, const StudySetting& setting);

/// The number at the dotted `key` of a setting's profile (the base's, where nothing sets it; for a
/// setting `of` another, that one's); true and false read 1 and 0; InputError naming the study,
/// the setting and the key.
double setting_number(const Study& study, const StudySetting& setting, const std::string& key);

}  // namespace softpack

// glint public API: an effect's settings as a table.
//
// Every tunable of an effect is one row: its name as a tool spells it ("thickness",
// "denoiser.historyClipScale", "shadows.antiLag"), its type, default, range, one line of help
// and the desc field it ends in. Parsing, range checks, error lines, command-line help and the
// settings tables in the docs all come from these rows, so a setting is declared once.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

enum class SettingType : std::uint8_t {
    Bool,   // true/false, on/off, 1/0
    Uint,   // a whole number in [minimum, maximum]
    Float,  // a finite number in [minimum, maximum]
    Choice, // one of `choices`; the value is its index
};

struct SettingDesc {
    std::string name;
    SettingType type = SettingType::Float;
    double defaultValue = 0.0; // Choice: the index of the default choice
    double minimum = 0.0;      // Uint and Float, inclusive
    double maximum = 0.0;
    std::vector<std::string> choices; // Choice only
    std::string help;                 // one line: what the setting does
    std::string target;               // where it goes, e.g. "SssrDesc::thickness"
};

// Values by setting name. Every name comes from a table; reading a name no table declared is a
// programming error (std::logic_error).
class SettingValues {
  public:
    SettingValues() = default;
    explicit SettingValues(const std::vector<const SettingDesc*>& table);

    // Parses and checks one "name=value"; empty on success, else one line naming the setting,
    // what it needs and what it got.
    std::string assign(std::string_view assignment);

    bool flag(std::string_view name) const;
    std::uint32_t count(std::string_view name) const;
    float real(std::string_view name) const;
    std::uint32_t choice(std::string_view name) const;

    bool has(std::string_view name) const;
    void set(std::string_view name, double value); // unchecked: for code, not for user input
    const std::vector<std::string>& assignments() const { return assignments_; }
    const std::vector<const SettingDesc*>& table() const { return table_; }

  private:
    double value(std::string_view name) const;
    std::vector<const SettingDesc*> table_;
    std::map<std::string, double, std::less<>> values_;
    std::vector<std::string> assignments_; // as given, for reports
};

// "name  type  default  range  help" lines of a table, for `glint settings` and --help.
std::string describeSettings(const std::vector<const SettingDesc*>& table);

// The same rows as a Markdown table (docs/settings.md is made of these, and a test keeps it so).
std::string settingsMarkdown(const std::vector<const SettingDesc*>& table);

// The value of a setting as a tool spells it ("true", "0.2", "prefilter").
std::string formatSettingValue(const SettingDesc& setting, double value);

} // namespace glint

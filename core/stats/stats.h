// Frame statistics: an ordered dictionary of named numbers, as in paper 000's Tables 1-7.
// Key names are the contract with every host; docs/statistics.md lists them.
#pragma once

#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace sheaf {

class Stats {
  public:
    void set(std::string_view key, double value);
    void add(std::string_view key, double value);
    /// 0 when absent.
    double get(std::string_view key) const;
    bool has(std::string_view key) const;
    const std::vector<std::pair<std::string, double>>& entries() const { return entries_; }

    /// One flat JSON object, keys in insertion order, integers printed exactly.
    std::string to_json() const;
    /// Reads what to_json wrote (a flat object of numbers; null as NaN). Throws
    /// std::invalid_argument at the first thing that is not such an entry.
    static Stats from_json(std::string_view json);
    /// The paper's tables as text: rays, tests per ray type and level, totals, time per phase.
    std::string to_table() const;

  private:
    std::vector<std::pair<std::string, double>> entries_;
    std::unordered_map<std::string, size_t> index_;
};

} // namespace sheaf

// EDS (CiA 306 electronic data sheet): load any EDS into an object dictionary, and write an
// object dictionary out as an EDS. Errors name the file and line.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "devices/canopen/object_dictionary.h"

namespace canopen {

/// [FileInfo] and [DeviceInfo] content.
struct EdsFileInfo {
  std::string file_name;       ///< e.g. "WAGMD2C1.eds"
  std::string description;
  std::string created_by = "vplant";
  std::string vendor_name;
  std::uint32_t vendor_number = 0;
  std::string product_name;
  std::uint32_t product_number = 0;
  std::uint32_t revision_number = 0;
  std::string order_code;
  std::vector<unsigned> baud_rates_kbit = {10, 20, 50, 125, 250, 500, 800, 1000};
  bool simple_boot_up_slave = true;
  bool lss_supported = false;
  std::uint8_t granularity = 8;
  bool dynamic_channels = false;
  std::uint8_t nr_of_rx_pdo = 0;  ///< filled from the dictionary when writing
  std::uint8_t nr_of_tx_pdo = 0;
};

struct EdsError {
  std::string file;
  int line = 0;  ///< 1-based; 0 = whole file (e.g. cannot open)
  std::string reason;
  std::string message() const;  ///< "file:line: reason"
};

/// Parses EDS text. On error returns nullopt and fills `error` (first error, with its line).
std::optional<ObjectDictionary> parse_eds(std::string_view text, const std::string& file_name, EdsError& error,
                                          EdsFileInfo* info = nullptr);
std::optional<ObjectDictionary> load_eds(const std::string& path, EdsError& error, EdsFileInfo* info = nullptr);
/// Writes `od` as an EDS (defaults as stored, node-relative defaults as $NODEID+x).
std::string write_eds(const ObjectDictionary& od, const EdsFileInfo& info);

}  // namespace canopen

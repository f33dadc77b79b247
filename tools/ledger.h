// `voxgi ledger SCENE --technique lpv|holpv`: where a light propagation volume's light goes, step
// by step (validation/lpv/ledger.h), as a table and as JSON.
#pragma once

#include <ostream>

#include <nlohmann/json.hpp>

#include "validation/lpv/ledger.h"

namespace voxgi::tools {

// Fractions of the emitted flux, luminance-weighted (Rec. 709) so one column stands for a colour.
void printLedger(std::ostream& out, const validation::Ledger& ledger);
nlohmann::json ledgerJson(const validation::Ledger& ledger);

}  // namespace voxgi::tools

#pragma once

namespace uabt::bench {

// `uabt_bench selection`: the tables of --selection optimized against Fig. 4 (condition ticks
// per selection, checked by the engine; compile time). Exit status 1 when a count disagrees
// with the engine or a node ticks more than under Fig. 4.
int selection_figures();

}  // namespace uabt::bench

#include "input/parameter_parsing.h"

#include <deal.II/base/utilities.h>

namespace penny
{
  std::vector<double> get_doubles(const dealii::ParameterHandler &prm, const std::string &entry)
  {
    return dealii::Utilities::string_to_double(dealii::Utilities::split_string_list(prm.get(entry)));
  }
} // namespace penny

#include <ltn/base/input_error.h>
#include <ltn/output/fracture_measurements.h>

#include <cmath>
#include <iomanip>
#include <memory>
#include <sstream>

namespace ltn
{
  namespace
  {
    JsonValue
    tensor_to_json(const double *values, const unsigned int n)
    {
      JsonValue array = JsonValue::array();
      for (unsigned int i = 0; i < n; ++i)
        array.push_back(values[i]);
      return array;
    }
  } // namespace



  template <int dim>
  std::string
  measure_section_forces(
    const ElasticityProblem<dim>                       &local,
    const TrilinosWrappers::MPI::Vector                &field,
    const std::vector<std::pair<unsigned int, double>> &planes,
    const Box<dim>                                     &body,
    JsonValue                                          &entry)
  {
    std::ostringstream report;
    report << std::setprecision(6);
    entry = JsonValue::array();
    for (const auto &[d, c] : planes)
      {
        const Tensor<1, dim> force = local.section_force(field, d, c);
        double               area  = 1;
        for (unsigned int e = 0; e < dim; ++e)
          if (e != d)
            area *= body.upper[e] - body.lower[e];
        JsonValue section      = JsonValue::object();
        section["plane"]       = std::string(1, "xyz"[d]) + "=" + to_string(c);
        section["force"]       = tensor_to_json(force.begin_raw(), dim);
        section["mean_stress"] = force[d] / area;
        report << "  force through "
               << "xyz"[d] << " = " << c << ": " << force << " (mean stress "
               << force[d] / area << ")\n";
        entry.push_back(section);
      }
    return report.str();
  }



  template <int dim>
  std::string
  measure_applied_forces(const ElasticityProblem<dim> &local,
                         const LocalParameters<dim>   &parameters,
                         const Function<dim>          &traction,
                         const Function<dim>          &pressure,
                         JsonValue                    &entry)
  {
    std::ostringstream report;
    report << std::setprecision(6);
    entry = JsonValue::array();
    for (unsigned int face = 0; face < 2 * dim; ++face)
      if (parameters.dirichlet_mask(face, dim).n_selected_components() < dim)
        {
          const Tensor<1, dim> force =
            local.applied_force(traction, pressure, face);
          if (force.norm() > 0)
            report << "  applied force on " << Geometry<dim>::face_name(face)
                   << ": " << force << "\n";
          JsonValue load = JsonValue::object();
          load["face"]   = Geometry<dim>::face_name(face);
          load["force"]  = tensor_to_json(force.begin_raw(), dim);
          entry.push_back(load);
        }
    return report.str();
  }



  template <int dim>
  std::string
  measure_crack_openings(const ParticleElasticity<dim>       &nonlocal,
                         const TrilinosWrappers::MPI::Vector &field,
                         const unsigned int                   n_cracks,
                         const Function<dim>                 *reference,
                         JsonValue                           &entry)
  {
    std::ostringstream report;
    report << std::setprecision(6);
    entry = JsonValue::array();
    for (unsigned int k = 0; k < n_cracks; ++k)
      {
        const auto opening = nonlocal.crack_opening(field, k);
        JsonValue  crack   = JsonValue::object();
        JsonValue  points  = JsonValue::array();
        JsonValue  values  = JsonValue::array();
        double     max = 0, difference = 0, norm = 0;
        for (std::size_t i = 0; i < opening.points.size(); ++i)
          {
            points.push_back(
              tensor_to_json(opening.points[i].begin_raw(), dim));
            values.push_back(opening.opening[i]);
            max = std::max(max, opening.opening[i]);
            if (reference)
              {
                const double r = reference->value(opening.points[i]);
                difference += std::pow(opening.opening[i] - r, 2);
                norm += r * r;
              }
          }
        const bool sampled  = !opening.points.empty();
        const bool compared = reference && sampled && norm > 0;
        report << "  crack " << k << ": ";
        if (sampled)
          report << "opening at " << opening.points.size()
                 << " particle pairs, max " << max;
        else
          report << "not measured: no particles face each other "
                    "across it half a spacing away";
        if (compared)
          report << ", relative L2 difference to the reference "
                 << std::sqrt(difference / norm);
        report << "\n";
        crack["points"]      = points;
        crack["opening"]     = values;
        crack["max_opening"] = sampled ? JsonValue(max) : JsonValue();
        if (compared)
          crack["relative_l2_difference_to_reference"] =
            std::sqrt(difference / norm);
        entry.push_back(crack);
      }
    return report.str();
  }



#define LTN_INSTANTIATE(dim)                                                  \
  template std::string measure_section_forces(                                \
    const ElasticityProblem<dim> &,                                           \
    const TrilinosWrappers::MPI::Vector &,                                    \
    const std::vector<std::pair<unsigned int, double>> &,                     \
    const Box<dim> &,                                                         \
    JsonValue &);                                                             \
  template std::string measure_applied_forces(const ElasticityProblem<dim> &, \
                                              const LocalParameters<dim> &,   \
                                              const Function<dim> &,          \
                                              const Function<dim> &,          \
                                              JsonValue &);                   \
  template std::string measure_crack_openings(                                \
    const ParticleElasticity<dim> &,                                          \
    const TrilinosWrappers::MPI::Vector &,                                    \
    unsigned int,                                                             \
    const Function<dim> *,                                                    \
    JsonValue &);
  LTN_INSTANTIATE(2)
  LTN_INSTANTIATE(3)
#undef LTN_INSTANTIATE
} // namespace ltn

#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <ltn/output/elasticity_output.h>
#include <ltn/output/field_output.h>
#include <ltn/output/parallel_vtu.h>

#include <cmath>
#include <vector>

namespace ltn
{
  namespace
  {
    /**
     * From the displacement: `strain` and `stress` (tensors, `dim x dim`,
     * row by row), `von_mises` and `region` at each output point.
     */
    template <int dim>
    class StrainAndStress : public DataPostprocessor<dim>
    {
    public:
      StrainAndStress(
        const Material                                  &material,
        const std::function<Region(const Point<dim> &)> &region_of)
        : lambda(material.lambda(dim))
        , mu(material.mu())
        , plane_stress(material.plane == Material::Plane::stress)
        , region_of(region_of)
      {}

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<dim> &inputs,
        std::vector<Vector<double>> &computed_quantities) const override
      {
        for (unsigned int q = 0; q < inputs.solution_gradients.size(); ++q)
          {
            SymmetricTensor<2, dim> strain;
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = i; j < dim; ++j)
                strain[i][j] = (inputs.solution_gradients[q][i][j] +
                                inputs.solution_gradients[q][j][i]) /
                               2;
            const SymmetricTensor<2, dim> stress =
              lambda * trace(strain) * unit_symmetric_tensor<dim>() +
              2 * mu * strain;

            Vector<double> &out = computed_quantities[q];
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                {
                  out[i * dim + j]             = strain[i][j];
                  out[dim * dim + i * dim + j] = stress[i][j];
                }

            // The 3D stress state; in 2D plane strain eps_zz = 0, in plane
            // stress sigma_zz = 0.
            SymmetricTensor<2, 3> stress_3d;
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = i; j < dim; ++j)
                stress_3d[i][j] = stress[i][j];
            if (dim == 2 && !plane_stress)
              stress_3d[2][2] = lambda * trace(strain);
            const SymmetricTensor<2, 3> s = deviator(stress_3d);
            out[2 * dim * dim]            = std::sqrt(1.5 * (s * s));
            out[2 * dim * dim + 1] =
              static_cast<double>(region_of(inputs.evaluation_points[q]));
          }
      }

      std::vector<std::string>
      get_names() const override
      {
        std::vector<std::string> names(dim * dim, "strain");
        names.insert(names.end(), dim * dim, "stress");
        names.emplace_back("von_mises");
        names.emplace_back("region");
        return names;
      }

      std::vector<DataComponentInterpretation::DataComponentInterpretation>
      get_data_component_interpretation() const override
      {
        std::vector<DataComponentInterpretation::DataComponentInterpretation>
          interpretation(
            2 * dim * dim,
            DataComponentInterpretation::component_is_part_of_tensor);
        interpretation.insert(interpretation.end(),
                              2,
                              DataComponentInterpretation::component_is_scalar);
        return interpretation;
      }

      UpdateFlags
      get_needed_update_flags() const override
      {
        return update_gradients | update_quadrature_points;
      }

    private:
      const double                                     lambda;
      const double                                     mu;
      const bool                                       plane_stress;
      const std::function<Region(const Point<dim> &)> &region_of;
    };
  } // namespace



  template <int dim>
  std::string
  write_elasticity_vtu(
    const DoFHandler<dim>                           &dof_handler,
    const TrilinosWrappers::MPI::Vector             &ghosted_field,
    const Material                                  &material,
    const Function<dim>                             *exact,
    const std::function<Region(const Point<dim> &)> &region_of,
    const std::string                               &directory,
    const std::string                               &name)
  {
    AssertThrow(dof_handler.get_fe().n_components() == dim,
                ExcDimensionMismatch(dof_handler.get_fe().n_components(), dim));
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
      vector_field(dim,
                   DataComponentInterpretation::component_is_part_of_vector);

    DataOut<dim> data_out;
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(ghosted_field,
                             std::vector<std::string>(dim, "displacement"),
                             DataOut<dim>::type_dof_data,
                             vector_field);
    const StrainAndStress<dim> strain_and_stress(material, region_of);
    data_out.add_data_vector(ghosted_field, strain_and_stress);

    std::array<TrilinosWrappers::MPI::Vector, 2> exact_and_error;
    if (exact != nullptr)
      {
        exact_and_error =
          nodal_exact_and_error(dof_handler, ghosted_field, *exact);
        data_out.add_data_vector(exact_and_error[0],
                                 std::vector<std::string>(dim,
                                                          "displacement_exact"),
                                 DataOut<dim>::type_dof_data,
                                 vector_field);
        data_out.add_data_vector(exact_and_error[1],
                                 std::vector<std::string>(dim, "error"),
                                 DataOut<dim>::type_dof_data,
                                 vector_field);
      }

    data_out.build_patches(dof_handler.get_fe().degree);
    return write_parallel_vtu(data_out,
                              directory,
                              name,
                              dof_handler.get_communicator());
  }

  template std::string
  write_elasticity_vtu(const DoFHandler<2> &,
                       const TrilinosWrappers::MPI::Vector &,
                       const Material &,
                       const Function<2> *,
                       const std::function<Region(const Point<2> &)> &,
                       const std::string &,
                       const std::string &);
  template std::string
  write_elasticity_vtu(const DoFHandler<3> &,
                       const TrilinosWrappers::MPI::Vector &,
                       const Material &,
                       const Function<3> *,
                       const std::function<Region(const Point<3> &)> &,
                       const std::string &,
                       const std::string &);
} // namespace ltn

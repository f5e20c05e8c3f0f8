#pragma once

// ModelDirectSolver against MUMPS's LU of a model's whole matrix, shared by
// the tests of the models whose free block it factorizes alone.

#include <ltn/base/direct_solver.h>
#include <ltn/model_solvers/model_direct_solver.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <vector>

#include "particle_layout.h"

/** |other - reference|_inf / |reference|_inf. */
inline double
relative_difference(const dealii::TrilinosWrappers::MPI::Vector &reference,
                    dealii::TrilinosWrappers::MPI::Vector        other)
{
  other -= reference;
  return other.linfty_norm() / reference.linfty_norm();
}

/**
 * M x = b and M^T x = b for random b (outside the free block too), one at a
 * time and together, by ModelDirectSolver and by the LU of the whole
 * matrix: the largest relative difference.
 */
inline double
difference_to_lu(const ltn::DiscreteModel &model)
{
  const ltn::ModelDirectSolver                       free_block(model);
  const ltn::DirectSolver                            lu(model.matrix);
  std::mt19937                                       random(7);
  std::vector<dealii::TrilinosWrappers::MPI::Vector> b;
  for (unsigned int j = 0; j < 3; ++j)
    b.push_back(random_vector(model, random));
  double worst = 0;
  for (const bool transpose : {false, true})
    {
      std::vector<dealii::TrilinosWrappers::MPI::Vector> together;
      free_block.solve(together, b, transpose);
      REQUIRE(together.size() == b.size());
      for (unsigned int j = 0; j < b.size(); ++j)
        {
          auto reference = model.new_vector(), one = model.new_vector();
          if (transpose)
            lu.solve_transposed(reference, b[j]);
          else
            lu.solve(reference, b[j]);
          free_block.solve(one, b[j], transpose);
          worst = std::max({worst,
                            relative_difference(reference, one),
                            relative_difference(reference, together[j])});
        }
    }
  return worst;
}

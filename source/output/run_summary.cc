#include <ltn/output/run_summary.h>

#include <cmath>
#include <limits>

namespace ltn
{
  double
  observed_rate(const double e_coarse,
                const double e_fine,
                const double h_coarse,
                const double h_fine)
  {
    // No rate between adaptive cycles of one level (same h).
    if (e_coarse <= 0 || e_fine <= 0 || h_coarse == h_fine)
      return std::numeric_limits<double>::quiet_NaN();
    return std::log(e_coarse / e_fine) / std::log(h_coarse / h_fine);
  }



  namespace
  {
    JsonValue
    norms_to_json(const ErrorNorms &e)
    {
      JsonValue j = JsonValue::object();
      j["l2"]     = e.l2();
      j["linf"]   = e.linf;
      return j;
    }

    JsonValue
    errors_to_json(const LevelRecord &level)
    {
      if (!level.has_errors)
        return JsonValue();
      JsonValue j   = JsonValue::object();
      j["nonlocal"] = norms_to_json(level.nonlocal_errors);
      j["local"]    = norms_to_json(level.local_errors);
      j["coupled"]  = norms_to_json(level.coupled_errors);
      return j;
    }

    void
    add_level_fields(JsonValue &j, const LevelRecord &level)
    {
      j["n_nonlocal_dofs"]      = level.n_nonlocal_dofs;
      j["n_local_dofs"]         = level.n_local_dofs;
      j["n_controls"]           = level.n_controls;
      j["horizon"]              = level.horizon;
      j["solver"]["method"]     = level.solver_method;
      j["solver"]["iterations"] = level.solver.iterations;
      j["solver"]["residual"]   = level.solver.residual;
      if (level.solver.true_residual >= 0)
        j["solver"]["true residual"] = level.solver.true_residual;
      if (level.solver.asymmetry >= 0)
        j["solver"]["asymmetry"] = level.solver.asymmetry;
      if (level.solver.explicit_controls > 0 || level.solver.coarse_modes > 0)
        {
          JsonValue &preconditioner = j["solver"]["control preconditioner"];
          preconditioner["explicit controls"] = level.solver.explicit_controls;
          preconditioner["coarse modes"]      = level.solver.coarse_modes;
          preconditioner["setup seconds"] =
            level.solver.preconditioner_setup_seconds;
          preconditioner["collar layer weight"] = level.collar_layer_weight;
          preconditioner["crack opening fields"] =
            level.solver.crack_opening_fields;
          if (level.solver.nonlocal_block_unknowns > 0)
            preconditioner["nonlocal block unknowns"] =
              level.solver.nonlocal_block_unknowns;
        }
      if (level.solver.largest_ritz_value > 0)
        {
          JsonValue &ritz  = j["solver"]["Ritz values"];
          ritz["smallest"] = level.solver.smallest_ritz_value;
          ritz["largest"]  = level.solver.largest_ritz_value;
        }
      if (level.solver.standalone_seconds > 0)
        j["solver"]["standalone model solves seconds"] =
          level.solver.standalone_seconds;
      const char *names[2] = {"nonlocal", "local"};
      if (!level.solver.phases.empty())
        {
          JsonValue phases = JsonValue::array();
          for (const auto &phase : level.solver.phases)
            {
              JsonValue entry  = JsonValue::object();
              entry["name"]    = phase.name;
              entry["seconds"] = phase.seconds;
              for (const unsigned int k : {0u, 1u})
                {
                  JsonValue &model    = entry[names[k]];
                  model["solves"]     = phase.model_solvers[k].solves;
                  model["iterations"] = phase.model_solvers[k].iterations;
                  model["seconds"]    = phase.model_solvers[k].seconds;
                }
              phases.push_back(entry);
            }
          j["solver"]["phases"] = phases;
        }
      for (const unsigned int k : {0u, 1u})
        if (const ModelSolverStatistics &solver = level.solver.model_solvers[k];
            solver.solves > 0)
          {
            JsonValue &model    = j["solver"]["model solvers"][names[k]];
            model["solves"]     = solver.solves;
            model["iterations"] = solver.iterations;
            model["iterations per solve"] =
              static_cast<double>(solver.iterations) / solver.solves;
            model["seconds"]                = solver.seconds;
            model["operator seconds"]       = solver.operator_seconds;
            model["preconditioner seconds"] = solver.preconditioner_seconds;
          }
      JsonValue &memory              = j["memory"];
      memory["nonlocal model bytes"] = level.model_bytes[0];
      memory["local model bytes"]    = level.model_bytes[1];
      if (level.n_particles > 0)
        memory["bytes per particle"] = level.model_bytes[0] / level.n_particles;
      if (level.n_local_dofs > 0)
        memory["bytes per local dof"] =
          level.model_bytes[1] / level.n_local_dofs;
      j["mismatch_J"] = level.mismatch_J;
      j["errors"]     = errors_to_json(level);
      if (!level.extras.is_null())
        j["mechanics"] = level.extras;
      if (const ModelErrorRecord &e = level.model_error; e.computed)
        {
          JsonValue &m        = j["model_error"];
          m["estimate"]       = e.estimate;
          m["estimate_short"] = e.estimate_short;
          m["estimate_long"]  = e.estimate_long;
          m["relative"]       = e.relative;
          m["boundary_layer"] = e.boundary_layer;
          m["chi"]            = e.chi;
          m["c_G"]            = e.c_G;
          m["points"]         = e.n_points;
          m["largest"]        = e.largest;
          JsonValue at        = JsonValue::array();
          for (const double x : e.largest_at)
            at.push_back(x);
          m["largest_at"] = at;
          if (e.has_true_error)
            {
              m["true_error"]    = e.true_error;
              m["true_relative"] = e.true_relative;
              m["effectivity"]   = e.effectivity;
            }
          if (e.has_region_error)
            {
              m["region_error"]       = e.region_error;
              m["region_relative"]    = e.region_relative;
              m["region_effectivity"] = e.region_effectivity;
            }
        }
    }
  } // namespace



  JsonValue
  RunSummary::to_json() const
  {
    JsonValue j = JsonValue::object();
    j["scene"]  = scene;
    j["dim"]    = dim;
    j["model"]  = model;
    add_level_fields(j, levels.back());
    j["h"] = levels.back().h;

    JsonValue timings = JsonValue::object();
    for (const auto &phase : levels.front().timings)
      {
        double sum = 0;
        for (const LevelRecord &level : levels)
          for (const auto &entry : level.timings)
            if (entry.first == phase.first)
              sum += entry.second;
        timings[phase.first] = sum;
      }
    timings["total"] = total_time;
    j["timings"]     = timings;
    j["memory_mb"]   = memory_mb;

    if (levels.size() > 1)
      {
        JsonValue convergence = JsonValue::array();
        for (std::size_t l = 0; l < levels.size(); ++l)
          {
            JsonValue entry = JsonValue::object();
            entry["level"]  = static_cast<unsigned int>(l);
            entry["cycle"]  = levels[l].cycle;
            entry["h"]      = levels[l].h;
            add_level_fields(entry, levels[l]);
            JsonValue level_timings = JsonValue::object();
            for (const auto &phase : levels[l].timings)
              level_timings[phase.first] = phase.second;
            entry["timings"] = level_timings;

            if (l > 0 && levels[l].has_errors)
              {
                const LevelRecord &c = levels[l - 1], &f = levels[l];
                const auto         rates = [&](const ErrorNorms &coarse,
                                       const ErrorNorms &fine) {
                  JsonValue r = JsonValue::object();
                  r["l2"] = observed_rate(coarse.l2(), fine.l2(), c.h, f.h);
                  r["linf"] = observed_rate(coarse.linf, fine.linf, c.h, f.h);
                  return r;
                };
                entry["rates"]["nonlocal"] =
                  rates(c.nonlocal_errors, f.nonlocal_errors);
                entry["rates"]["local"] = rates(c.local_errors, f.local_errors);
                entry["rates"]["coupled"] =
                  rates(c.coupled_errors, f.coupled_errors);
              }
            else
              entry["rates"] = JsonValue();
            convergence.push_back(entry);
          }
        j["convergence"] = convergence;
      }

    if (model_adaptivity.enabled)
      {
        JsonValue &m     = j["model_adaptivity"];
        m["tolerance"]   = model_adaptivity.tolerance;
        m["block_size"]  = model_adaptivity.block_size;
        m["stopped"]     = model_adaptivity.cycles.empty() ?
                             std::string() :
                             model_adaptivity.cycles.back().stopped;
        JsonValue cycles = JsonValue::array();
        for (const ModelCycleRecord &cycle : model_adaptivity.cycles)
          {
            const ModelErrorRecord &e = levels[cycle.level_entry].model_error;
            JsonValue               entry = JsonValue::object();
            entry["cycle"]                = cycle.cycle;
            entry["level_entry"]          = cycle.level_entry;
            JsonValue boxes               = JsonValue::array();
            for (const auto &box : cycle.boxes)
              {
                JsonValue numbers = JsonValue::array();
                for (const double x : box)
                  numbers.push_back(x);
                boxes.push_back(numbers);
              }
            entry["boxes"]             = boxes;
            entry["blocks"]            = cycle.blocks;
            entry["particles"]         = cycle.particles;
            entry["estimate"]          = cycle.estimate;
            entry["estimate_absolute"] = cycle.estimate_absolute;
            entry["estimate_coupling"] = cycle.estimate_coupling;
            entry["true_error"] =
              e.has_region_error ? JsonValue(e.region_relative) : JsonValue();
            entry["effectivity"] = e.has_region_error ?
                                     JsonValue(e.region_effectivity) :
                                     JsonValue();
            entry["true_error_whole_body_reference"] =
              e.has_true_error ? JsonValue(e.true_relative) : JsonValue();
            entry["marked"]  = cycle.marked;
            entry["added"]   = cycle.added;
            entry["stopped"] = cycle.stopped;
            cycles.push_back(entry);
          }
        m["cycles"] = cycles;
      }
    return j;
  }
} // namespace ltn

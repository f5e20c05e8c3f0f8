#include <ltn/problem/block_grid.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace ltn
{
  template <int dim>
  BlockGrid<dim>::BlockGrid(const Box<dim> &body, const double block_size)
    : body(body)
    , size(block_size)
  {
    for (unsigned int d = 0; d < dim; ++d)
      counts[d] = static_cast<unsigned int>(
        std::ceil((body.upper[d] - body.lower[d]) / size - 1e-9));
  }



  template <int dim>
  unsigned int
  BlockGrid<dim>::n_blocks() const
  {
    unsigned int n = 1;
    for (unsigned int d = 0; d < dim; ++d)
      n *= counts[d];
    return n;
  }



  template <int dim>
  std::array<unsigned int, dim>
  BlockGrid<dim>::coordinates(unsigned int k) const
  {
    std::array<unsigned int, dim> c;
    for (unsigned int d = 0; d < dim; ++d)
      {
        c[d] = k % counts[d];
        k /= counts[d];
      }
    return c;
  }



  template <int dim>
  unsigned int
  BlockGrid<dim>::number(const std::array<unsigned int, dim> &c) const
  {
    unsigned int k = 0;
    for (int d = dim - 1; d >= 0; --d)
      k = k * counts[d] + c[d];
    return k;
  }



  template <int dim>
  Box<dim>
  BlockGrid<dim>::block(const unsigned int k) const
  {
    const auto c = coordinates(k);
    Box<dim>   box;
    for (unsigned int d = 0; d < dim; ++d)
      {
        box.lower[d] = body.lower[d] + c[d] * size;
        box.upper[d] =
          std::min(body.lower[d] + (c[d] + 1) * size, body.upper[d]);
      }
    return box;
  }



  template <int dim>
  unsigned int
  BlockGrid<dim>::block_of(const Point<dim> &p) const
  {
    std::array<unsigned int, dim> c;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double t = std::floor((p[d] - body.lower[d]) / size + 1e-9);
        c[d]           = static_cast<unsigned int>(
          std::clamp(t, 0., static_cast<double>(counts[d] - 1)));
      }
    return number(c);
  }



  template <int dim>
  typename BlockGrid<dim>::Set
  BlockGrid<dim>::covering(const Box<dim> &box) const
  {
    const double tol = 1e-9 * size;
    Set          set(n_blocks(), false);
    for (unsigned int k = 0; k < n_blocks(); ++k)
      {
        const Box<dim> b    = block(k);
        bool           meet = true;
        for (unsigned int d = 0; d < dim; ++d)
          meet = meet && b.lower[d] < box.upper[d] - tol &&
                 box.lower[d] < b.upper[d] - tol;
        set[k] = meet;
      }
    return set;
  }



  template <int dim>
  typename BlockGrid<dim>::Set
  BlockGrid<dim>::inside(const double room) const
  {
    const double tol = 1e-9 * size;
    Set          set(n_blocks(), false);
    for (unsigned int k = 0; k < n_blocks(); ++k)
      {
        const Box<dim> b  = block(k);
        bool           in = true;
        for (unsigned int d = 0; d < dim; ++d)
          in = in && b.lower[d] - body.lower[d] >= room - tol &&
               body.upper[d] - b.upper[d] >= room - tol;
        set[k] = in;
      }
    return set;
  }



  template <int dim>
  std::vector<unsigned int>
  BlockGrid<dim>::face_neighbours(const unsigned int k) const
  {
    std::vector<unsigned int> neighbours;
    const auto                c = coordinates(k);
    for (unsigned int d = 0; d < dim; ++d)
      for (const int step : {-1, 1})
        {
          auto n = c;
          if ((step < 0 && c[d] == 0) || (step > 0 && c[d] + 1 == counts[d]))
            continue;
          n[d] += step;
          neighbours.push_back(number(n));
        }
    return neighbours;
  }



  template <int dim>
  typename BlockGrid<dim>::Set
  BlockGrid<dim>::window(const unsigned int k,
                         const unsigned int radius,
                         const Set         &within) const
  {
    // The index box of `within`.
    std::array<int, dim> low, high;
    low.fill(std::numeric_limits<int>::max());
    high.fill(-1);
    for (unsigned int b = 0; b < n_blocks(); ++b)
      if (within[b])
        {
          const auto c = coordinates(b);
          for (unsigned int d = 0; d < dim; ++d)
            {
              low[d]  = std::min(low[d], static_cast<int>(c[d]));
              high[d] = std::max(high[d], static_cast<int>(c[d]));
            }
        }
    const auto           centre = coordinates(k);
    std::array<int, dim> first;
    for (unsigned int d = 0; d < dim; ++d)
      first[d] = std::max(low[d],
                          std::min(static_cast<int>(centre[d]) - int(radius),
                                   high[d] - 2 * int(radius)));
    Set set(n_blocks(), false);
    for (unsigned int b = 0; b < n_blocks(); ++b)
      {
        const auto c  = coordinates(b);
        bool       in = within[b];
        for (unsigned int d = 0; d < dim; ++d)
          in = in && int(c[d]) >= first[d] &&
               int(c[d]) <= first[d] + 2 * int(radius);
        set[b] = in;
      }
    return set;
  }



  template <int dim>
  std::vector<std::vector<unsigned int>>
  BlockGrid<dim>::pieces(const Set &set) const
  {
    std::vector<std::vector<unsigned int>> result;
    std::vector<bool>                      seen(n_blocks(), false);
    for (unsigned int k = 0; k < n_blocks(); ++k)
      if (set[k] && !seen[k])
        {
          std::vector<unsigned int> piece{k}, stack{k};
          seen[k] = true;
          while (!stack.empty())
            {
              const unsigned int b = stack.back();
              stack.pop_back();
              for (const unsigned int n : face_neighbours(b))
                if (set[n] && !seen[n])
                  {
                    seen[n] = true;
                    piece.push_back(n);
                    stack.push_back(n);
                  }
            }
          std::sort(piece.begin(), piece.end());
          result.push_back(piece);
        }
    return result;
  }



  template <int dim>
  std::vector<Box<dim>>
  BlockGrid<dim>::boxes(const Set &set) const
  {
    std::vector<Box<dim>> result;
    std::vector<bool>     taken(n_blocks(), false);
    const auto            free = [&](const std::array<unsigned int, dim> &c) {
      const unsigned int k = number(c);
      return set[k] && !taken[k];
    };
    for (unsigned int k = 0; k < n_blocks(); ++k)
      if (set[k] && !taken[k])
        {
          const auto                    start = coordinates(k);
          std::array<unsigned int, dim> end   = start; // inclusive
          for (unsigned int d = 0; d < dim; ++d)
            while (end[d] + 1 < counts[d])
              {
                // The slab one further along d, over the extent so far.
                bool                          whole = true;
                std::array<unsigned int, dim> c     = start;
                c[d]                                = end[d] + 1;
                std::function<void(unsigned int)> walk;
                walk = [&](const unsigned int e) {
                  if (!whole)
                    return;
                  if (e == dim)
                    {
                      whole = free(c);
                      return;
                    }
                  if (e == d)
                    return walk(e + 1);
                  for (c[e] = start[e]; c[e] <= end[e] && whole; ++c[e])
                    walk(e + 1);
                };
                walk(0);
                if (!whole)
                  break;
                ++end[d];
              }
          Box<dim> box = block(k);
          box.upper    = block(number(end)).upper;
          // Take the box's blocks.
          std::array<unsigned int, dim>     c = start;
          std::function<void(unsigned int)> take;
          take = [&](const unsigned int e) {
            if (e == dim)
              {
                taken[number(c)] = true;
                return;
              }
            for (c[e] = start[e]; c[e] <= end[e]; ++c[e])
              take(e + 1);
          };
          take(0);
          result.push_back(box);
        }
    return result;
  }



  template <int dim>
  unsigned int
  BlockGrid<dim>::count(const Set &set)
  {
    return static_cast<unsigned int>(std::count(set.begin(), set.end(), true));
  }

  template class BlockGrid<1>;
  template class BlockGrid<2>;
  template class BlockGrid<3>;
} // namespace ltn

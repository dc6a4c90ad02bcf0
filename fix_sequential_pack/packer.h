// The class Packer, the state and steps of one packing (front_packer.h says
// what it does). Internal: its steps are spread by concept over
//   front_packer.cpp   construction, the deck and the draw, the first face,
//                      run() and its steps
//   packer_sites.cpp   the sites: where a grain on a site goes, the heaps of
//                      sites per size, the sites a new sphere opens
//   vacancies.cpp      the vacancy choice and the second loop
#ifndef FABRIC_PACKER_H
#define FABRIC_PACKER_H

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "arrangement_rule.h"
#include "cell_shares.h"
#include "front_packer.h"
#include "random_stream.h"
#include "site_heap.h"
#include "sphere_grid.h"
#include "trilateration.h"

namespace fabric {
namespace detail {

class Packer {
 public:
  explicit Packer(const PackingSpec& spec);
  PackingResult run();

 private:
  // What a site's position depends on besides the grain's radius: its
  // spheres and, for three, their face frame, computed once however many
  // sizes the site is offered (bit-identical to computing them each time).
  struct Geometry {
    int spheres = 0;
    Sphere sphere[3];
    std::optional<FaceFrame> frame;
  };
  Geometry geometry(const Site& s) const;
  std::optional<Vec3> position(const Site& s, const Geometry& g, double r,
                               Placement& how) const;
  bool inside(const Vec3& c, double r) const;
  double key_of(const Vec3& c) const;
  double wall_gap(int w, const Vec3& c, double r) const;
  Sphere support(int i) const { return grid_.sphere(i); }
  void open_sites(int p);
  void add_site(int a, int b, int c);
  void push(Site s, int level, const Geometry& g);
  void push(const Site& s, int level) { push(s, level, geometry(s)); }
  bool pop_lowest(int min_level, Site& s, int& level);
  void refresh_front(int level);
  void demote(const Site& s, int k, const Geometry& g);
  struct Front {
    double key;
    std::uint32_t order;
  };
  std::vector<Front> front_;  // per level: key and order of its heap's top
  int take_from_deck(const double* w, int n, double total);
  int draw();
  int place(const Vec3& c, int k, Placement how);
  bool try_site(Site& s, int k, const Geometry& g);
  void first_face();
  // The steps of run(), besides first_face, choose_vacancies and second_loop.
  void open_corner_sites();
  void pack_full();
  void take_specimen();
  void tally();
  void choose_vacancies();
  void make_vacant(int i);
  void remove_coarse(std::vector<int>& v, long long removals, int k);
  void remove_fines(const std::vector<int>& v, long long removals);
  CellShares cells_;          // the vacancy choice's cells
  std::vector<double> lose_;  // per cell: solid volume it still has to lose
  void second_loop();
  void fill_vacancy(int hole, int k);
  void report_progress();

  const PackingSpec& spec_;
  SphereGrid grid_;
  int nclass_ = 0;
  std::vector<int> asc_;    // classes by radius, finest first
  std::vector<int> rank_;   // class -> its position in asc_
  std::vector<int> below_;  // rank -> largest rank of a smaller radius, or -1
  std::vector<double> volume_;
  std::unique_ptr<Rule> rule_;  // DA or LA: which size is drawn next
  std::vector<std::vector<Site>> heap_;  // per rank: sites for sizes <= it
  // The grains come from decks, each deck the particle list once, shuffled
  // by drawing without replacement; the next deck opens when one is spent.
  std::vector<long long> deck_, deck_size_;
  long long deck_total_ = 0;
  double placed_volume_ = 0.0, list_volume_ = 0.0;

  // No open site takes a size of this rank or above (until a site opens
  // for one); such grains are not drawn, they stay in the deck.
  int blocked_ = 0;
  void new_deck();
  long long total_ = 0, next_report_ = 0;
  std::vector<std::uint8_t> vacant_;     // per placed sphere: 1 a vacancy
  std::vector<Placement> how_;           // per placed sphere
  std::vector<long long> missing_;       // per class: list count not placed
  Random rng_, vacancy_rng_;
  Vec3 centre_;
  double gap_ = 0.0;             // supports of a site lie within this gap
  std::uint32_t next_order_ = 0;
  std::vector<int> near_;        // scratch: neighbours of a new sphere
  std::size_t peak_sites_ = 0, live_sites_ = 0;
  PackingResult res_;
};

}  // namespace detail
}  // namespace fabric

#endif

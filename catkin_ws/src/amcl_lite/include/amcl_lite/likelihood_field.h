// amcl's likelihood-field map: for every cell, the distance to the nearest occupied cell,
// capped at laser_likelihood_max_dist. Built once per map; looked up for every beam end.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace amcl_lite {

// An occupancy grid as nav_msgs/OccupancyGrid lays it out: row-major from the origin corner,
// values -1 (unknown) or 0..100. The origin's yaw is taken to be zero (map_server's maps).
struct GridMap {
  double resolution = 0.05;
  double origin_x = 0.0;
  double origin_y = 0.0;
  int width = 0;
  int height = 0;
  std::vector<int8_t> cells;
};

// Why an initial pose (mean x, y; variances cov_xx, cov_yy) is no pose on `map`, or "" when
// it is one: its mean must lie on the map and its spread be narrower than the map's diagonal.
// Wider, nearly every particle lands off the map and the estimate runs away (a variance of
// 1e300 put amcl's pose at 1e147 m for good); global localization is what spreads particles
// over the whole map.
std::string initialPoseProblem(const GridMap& map, double x, double y, double cov_xx, double cov_yy);

class LikelihoodField {
 public:
  // Cells with values >= occupied_threshold are obstacles; 0 <= value < free_threshold free.
  LikelihoodField(const GridMap& map, double max_dist, int occupied_threshold = 65,
                  int free_threshold = 25);

  // Distance (m) from (x, y) to the nearest obstacle; max_dist outside the map.
  double distance(double x, double y) const;
  bool isFree(double x, double y) const;
  // Centres (x, y) of every free cell: where global localization may put the robot.
  const std::vector<std::pair<double, double>>& freeCells() const { return free_cells_; }
  double maxDist() const { return max_dist_; }
  double resolution() const { return map_.resolution; }

 private:
  bool cellOf(double x, double y, int* col, int* row) const;

  GridMap map_;
  double max_dist_;
  std::vector<float> distance_;
  std::vector<uint8_t> free_;
  std::vector<std::pair<double, double>> free_cells_;
};

}  // namespace amcl_lite

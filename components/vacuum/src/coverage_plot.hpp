#pragma once
// The cleaned-percentage plot of a vacuum run (QtCharts): bars of the gain in each 100 s of sim
// time and the cumulative curve, over the run's duration (900 s by default). It shows a student
// when the algorithm stops finding new floor.

#include <QtCharts/QChartView>

namespace QtCharts {
class QBarSet;
class QLineSeries;
class QValueAxis;
}  // namespace QtCharts

namespace aula::vacuum {

class CoveragePlot : public QtCharts::QChartView {
  Q_OBJECT
 public:
  CoveragePlot(double duration_s, QWidget* parent = nullptr);
  // One sample: coverage (percent of the free floor) at t_s of sim time since Run.
  void addSample(double t_s, double percent);
  void clear();

 private:
  double duration_s_;
  QtCharts::QBarSet* gains_ = nullptr;
  QtCharts::QLineSeries* cumulative_ = nullptr;
  QtCharts::QValueAxis* percent_axis_ = nullptr;
  int bin_ = -1;            // the 100 s bin of the last sample
  double bin_start_percent_ = 0, last_percent_ = 0, last_t_s_ = -1;
};

}  // namespace aula::vacuum

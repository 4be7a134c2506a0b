#include "parking_referee_window.hpp"

#include <aula/gui/shown_text.hpp>

#include <QGridLayout>
#include <QPushButton>

#include <cmath>

namespace aula::autopark {

ParkingRefereeWindow::ParkingRefereeWindow(ParkingRefereeNode& node) : node_(node) {
  setWindowTitle("Autopark referee");
  auto* layout = new QGridLayout(this);
  clock_ = new QLabel(this);
  clock_->setStyleSheet("font-size: 28px; font-family: monospace;");
  distances_ = new QLabel(this);
  distances_->setStyleSheet("font-family: monospace;");
  mark_ = new gui::MarkLabel(this);
  // Not the heading: the angle between the car's axis and the curb (a car parked backwards is aligned).
  orientation_ = new gui::Gauge("Angle to curb", "deg", -90, 90, 180, this);
  const QColor green(90, 190, 90), orange(240, 160, 40), red(220, 60, 60);
  orientation_->setBands({{-90, -45, red}, {-45, -15, orange}, {-15, 15, green}, {15, 45, orange}, {45, 90, red}});
  orientation_->setMinimumSize(200, 200);
  collisions_ = new QProgressBar(this);
  collisions_->setRange(0, 5);
  collisions_->setFormat("collisions: %v");
  collisions_->setStyleSheet("QProgressBar::chunk { background: rgb(220, 60, 60); }");
  auto* show = new QPushButton("Show me my mark", this);
  layout->addWidget(new QLabel("Sim time since Run", this), 0, 0);
  layout->addWidget(show, 0, 1);
  layout->addWidget(clock_, 1, 0);
  layout->addWidget(distances_, 1, 1, 2, 1);
  layout->addWidget(orientation_, 2, 0, 2, 1);
  layout->addWidget(collisions_, 3, 1);
  layout->addWidget(mark_, 4, 0, 1, 2);
  mark_->setMinimumHeight(90);
  connect(show, &QPushButton::clicked, this, &ParkingRefereeWindow::showMark);
  connect(&timer_, &QTimer::timeout, this, &ParkingRefereeWindow::refresh);
  timer_.start(50);
  refresh();
}

void ParkingRefereeWindow::refresh() {
  const ParkingReferee& r = node_.referee();
  const double t = r.elapsedS();
  clock_->setText(QString::fromStdString(node_.clockText(t)));  // stopped where the grading stopped
  if (mark_->clearFor(node_.episode())) gui::sayShown(*this, {clock_, mark_});
  const ParkingMeasures& m = r.measures();
  distances_->setText(QString("Front car: %1 m\nRear car:  %2 m  (centred: %6 m each)\nCurb:      %3 m\nTo the ideal pose: %4 m\n%5")
                          .arg(m.front_gap_m, 5, 'f', 2)
                          .arg(m.rear_gap_m, 5, 'f', 2)
                          .arg(m.curb_gap_m, 5, 'f', 2)
                          .arg(m.position_error_m, 0, 'f', 2)
                          .arg(r.parked() ? "PARKED" : m.inside_slot ? "in the slot" : "not in the slot")
                          .arg(m.ideal_gap_m, 0, 'f', 2));
  orientation_->setValue(m.yaw_error_deg);
  collisions_->setValue(static_cast<int>(std::min<long long>(r.collisions(), collisions_->maximum())));
  collisions_->setFormat(QString("collisions: %1 (%2 s)").arg(r.collisions()).arg(r.contactS(), 0, 'f', 1));
}

void ParkingRefereeWindow::showMark() {
  const ParkingReferee& r = node_.referee();
  const ParkingScores s = r.scores();
  const auto& end = node_.episodeEnd();  // ended: the report's mark, final
  mark_->setText(QString("Mark: %1 / 10%2\nangle %3 + time %4 + distances %5 + collisions %6 (x 0.025)")
                     .arg(end ? end->mark : s.mark, 0, 'f', 2)
                     .arg(end ? "" : " (so far)")
                     .arg(s.angle, 0, 'f', 0)
                     .arg(s.time, 0, 'f', 0)
                     .arg(s.distance, 0, 'f', 1)
                     .arg(s.collision, 0, 'f', 0));
  if (end) {
    refresh();
    gui::sayShown(*this, {clock_, mark_});
  }
}

}  // namespace aula::autopark

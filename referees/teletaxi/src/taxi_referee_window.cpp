#include "taxi_referee_window.hpp"

#include <aula/geometry/angles.hpp>
#include <aula/gui/shown_text.hpp>

#include <QGridLayout>
#include <QPushButton>

#include <cmath>

namespace aula::teletaxi {

TaxiRefereeWindow::TaxiRefereeWindow(TaxiRefereeNode& node) : node_(node) {
  setWindowTitle("TeleTaxi referee");
  auto* layout = new QGridLayout(this);
  clock_ = new QLabel(this);
  clock_->setStyleSheet("font-size: 28px; font-family: monospace;");
  distances_ = new QLabel(this);
  mark_ = new gui::MarkLabel(this);
  speed_ = new gui::Gauge("Speed", "km/h", 0, 80, 270, this);
  speed_->setBands({{0, 50, QColor(90, 190, 90)}, {50, 65, QColor(240, 160, 40)}, {65, 80, QColor(220, 60, 60)}});
  heading_ = new gui::Gauge("Heading", "deg", -180, 180, 360, this);
  heading_->setWorldHeading(true);
  auto* show = new QPushButton("Show me my mark", this);
  layout->addWidget(new QLabel("Sim time since GO!", this), 0, 0, 1, 2);
  layout->addWidget(clock_, 1, 0, 1, 2);
  layout->addWidget(distances_, 2, 0, 1, 2);
  layout->addWidget(speed_, 3, 0);
  layout->addWidget(heading_, 3, 1);
  layout->addWidget(show, 4, 0, 1, 2);
  layout->addWidget(mark_, 5, 0, 1, 2);
  speed_->setMinimumSize(190, 190);
  heading_->setMinimumSize(190, 190);
  mark_->setMinimumHeight(110);
  connect(show, &QPushButton::clicked, this, &TaxiRefereeWindow::showMark);
  connect(&timer_, &QTimer::timeout, this, &TaxiRefereeWindow::refresh);
  timer_.start(50);
  refresh();
}

void TaxiRefereeWindow::refresh() {
  const TaxiReferee& r = node_.referee();
  const double t = r.elapsedS();
  clock_->setText(QString::fromStdString(node_.clockText(t)));  // stopped where the grading stopped
  if (mark_->clearFor(node_.episode())) gui::sayShown(*this, {clock_, mark_});
  distances_->setText(r.hasGoal() ? QString("Straight line start -> destination: %1 m\nTravelled: %2 m\nTo the destination: %3 m")
                                        .arg(r.straightDistanceM(), 0, 'f', 1)
                                        .arg(r.pathLengthM(), 0, 'f', 1)
                                        .arg(r.distanceToGoalM(), 0, 'f', 1)
                                  : QString("Waiting for a destination (double-click on the TeleTaxi map)"));
  speed_->setValue(r.speedMps() * 3.6);
  heading_->setValue(geometry::headingDeg(r.yawRad()));  // the one convention, as in the component
}

void TaxiRefereeWindow::showMark() {
  const TaxiReferee& r = node_.referee();
  const TaxiGrade g = r.finished() ? r.grade() : r.provisionalGrade();
  const auto& end = node_.episodeEnd();  // ended: the report's mark, final
  mark_->setText(QString("Mark: %1 / 10%2\n%3")
                     .arg(end ? end->mark : g.mark, 0, 'f', 2)
                     .arg(end ? "" : " (so far)")
                     .arg(QString::fromStdString(end && end->how == "Stopped" ? end->why : g.verdict)));
  if (end) {
    refresh();
    gui::sayShown(*this, {clock_, mark_});
  }
}

}  // namespace aula::teletaxi

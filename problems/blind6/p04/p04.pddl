; Panda: open the bin, take the widget from the feeder, scan it over the
; scanner, drop it in the bin, press the button (10 actions: 4 moves, pick,
; place, and 3 symbolic actions).
(define (problem blind6-p04)
  (:domain blind6-station)
  (:objects widget - part
            home feeder scanner bin button - spot)
  (:init (at widget feeder) (arm-at home) (hand-empty)
         (accessible home) (accessible feeder) (accessible scanner)
         (accessible button) (has-lid bin)
         (is-scanner scanner) (is-button button) (is-bin bin))
  (:goal (and (sealed) (at widget bin))))

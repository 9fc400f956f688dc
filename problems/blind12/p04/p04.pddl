;; Three 4 cm spools stand in a line 6 cm apart (centre to centre) on a
;; rack; the middle one, 2 cm lower than the others, goes to the tray.
(define (problem blind12-p04)
  (:domain blind12-spools)
  (:objects spool-a spool-b spool-c - spool
            rack tray spare - holder)
  (:init (on spool-a rack) (on spool-b rack) (on spool-c rack))
  (:goal (on spool-b tray)))

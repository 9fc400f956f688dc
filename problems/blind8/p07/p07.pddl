;; KUKA iiwa: five things sorted by colour into two rimmed trays; r2 starts
;; stacked on b1; two tall movable distractors stand in the workspace.
(define (problem blind8-p07)
  (:domain blind8-sort)
  (:objects r1 r2 r3 b1 b2 m1 m2 - thing
            z-r1 z-r3 z-b1 z-b2 z-m1 z-m2 red-tray blue-tray - zone)
  (:init (in r1 z-r1) (in r3 z-r3) (in b1 z-b1) (in b2 z-b2)
         (in m1 z-m1) (in m2 z-m2) (on r2 b1)
         (clear r1) (clear r2) (clear r3) (clear b2) (clear m1) (clear m2)
         (handempty))
  (:goal (and (in r1 red-tray) (in r2 red-tray) (in r3 red-tray)
              (in b1 blue-tray) (in b2 blue-tray))))

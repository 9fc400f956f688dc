;; Planar disk: two crates from the west room to the east room through a
;; doorway that a plug fills; the plug must end in the doorway again.
(define (problem blind8-p04)
  (:domain blind8-haul)
  (:objects c1 c2 plug - load
            a1 a2 zone-1 zone-2 doorway park - area)
  (:init (at c1 a1) (at c2 a2) (at plug doorway) (unloaded))
  (:goal (and (at c1 zone-1) (at c2 zone-2) (at plug doorway))))

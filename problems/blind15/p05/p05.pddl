; blind15 p05: a cube right beside the KUKA's base goes out near its reach
; limit, and a cube at the reach limit comes in to the middle; a third
; cube (mid-range) goes behind the base.
(define (problem p05)
  (:domain kuka-reach)
  (:objects near far mid - item
            near-home far-home mid-home out-zone in-zone back-zone - zone)
  (:init (at near near-home) (at far far-home) (at mid mid-home)
         (dest near out-zone) (dest far in-zone) (dest mid back-zone)
         (handempty))
  (:goal (forall (?o - item)
           (exists (?z - zone) (and (dest ?o ?z) (at ?o ?z))))))

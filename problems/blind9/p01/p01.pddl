;; Panda: a tin taken 0.693 m out on the table and stowed on a wall
;; shelf whose board is 26.2 cm above the table.
(define (problem blind9-p01)
  (:domain blind9-restock)
  (:objects tin - container
            counter shelf - spot)
  (:init (stands tin counter) (hand-free))
  (:goal (stands tin shelf)))
